#include "telemetry/progress.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>
#include <unistd.h>


namespace lc::farm {

std::string format_duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  const long t = std::lround(s);
  if (t >= 3600) return fmt::format("{}h{:02d}m", t / 3600, (t % 3600) / 60);
  if (t >= 60) return fmt::format("{}m{:02d}s", t / 60, t % 60);
  return fmt::format("{}s", t);
}

std::string format_count(double v) {
  if (v >= 1e9) return fmt::format("{:.2f}G", v / 1e9);
  if (v >= 1e6) return fmt::format("{:.2f}M", v / 1e6);
  if (v >= 1e3) return fmt::format("{:.1f}k", v / 1e3);
  return fmt::format("{:.0f}", v);
}

// ETA from the average rate so far, measured in image rows (a preview row
// costs what a full one does).
std::string progress_line(const RunProgress& p, double seconds) {
  const double frac = p.rows_total > 0 ? static_cast<double>(p.rows_done) / p.rows_total : 1.0;
  std::string line = fmt::format("{}/{} frames", p.frames_stored, p.frames_total);
  if (p.previews_total > 0 && p.previews_stored < p.previews_total)
    line += fmt::format(" (previews {}/{})", p.previews_stored, p.previews_total);
  line += fmt::format(", {:.0f}%, {} rays/s", 100 * frac, format_count(seconds > 0 ? p.stats.rays / seconds : 0.0));
  if (p.rows_done > 0 && frac < 1.0)
    line += ", ETA " + format_duration(seconds * (1.0 - frac) / frac);
  return line;
}

Progress::Progress(ProgressStyle style, double interval, std::FILE* out)
    : style_(style), interval_(interval), out_(out), start_(std::chrono::steady_clock::now()), last_(start_) {}

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::tick(const RunProgress& p) {
  if (style_ == ProgressStyle::quiet) return;
  const auto now = std::chrono::steady_clock::now();
  const double since = std::chrono::duration<double>(now - last_).count();
  const double due = style_ == ProgressStyle::live ? 0.25 : interval_;
  if (since < due) return;
  last_ = now;
  const std::string line = progress_line(p, elapsed());
  if (style_ == ProgressStyle::live) {
    // Carriage return, the line, clear to the end of the terminal line.
    fmt::print(out_, "\rrender: {}\x1b[K", line);
    drawn_ = true;
  } else {
    fmt::print(out_, "render: {}\n", line);
  }
  std::fflush(out_);
}

void Progress::finish() {
  if (drawn_) fmt::print(out_, "\r\x1b[K");
  drawn_ = false;
  std::fflush(out_);
}

StepProgress::StepProgress(std::string what, std::size_t total, double interval, std::function<void()> check,
                           double first, std::FILE* out)
    : what_(std::move(what)), total_(total), interval_(interval), first_(std::min(first, interval)),
      check_(std::move(check)), out_(out), start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void StepProgress::operator()(std::size_t done) {
  if (check_) check_();
  if (interval_ <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  const double due = said_ ? interval_ : first_;
  if (std::chrono::duration<double>(now - last_).count() < due) return;
  last_ = now;
  say(done);
}

void StepProgress::say(std::size_t done) {
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  fmt::print(out_, "render: {}: {}/{} frames, {:.0f}%, {:.1f} s\n", what_, done, total_,
             total_ > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0, seconds);
  std::fflush(out_);
  said_ = true;
}

ProgressStyle progress_style_for(std::FILE* out, double interval) {
  if (::isatty(::fileno(out))) return ProgressStyle::live;
  return interval > 0 ? ProgressStyle::plain : ProgressStyle::quiet;
}

}  // namespace lc::farm
