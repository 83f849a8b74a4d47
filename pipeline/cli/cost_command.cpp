#include "cost_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "command_output.hpp"
#include "store/journal.hpp"

namespace lc {
namespace {

// The one journal in a render directory (DIR/<shot>.journal).
std::filesystem::path journal_in(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir))
    throw std::invalid_argument(fmt::format("{}: not a directory (give a render's --out directory)", dir.string()));
  std::vector<std::filesystem::path> found;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".journal") found.push_back(e.path());
  if (found.empty())
    throw std::invalid_argument(
        fmt::format("{}: no journal (*.journal) here: not a directory `lightcone render` wrote", dir.string()));
  if (found.size() > 1)
    throw std::invalid_argument(fmt::format("{}: {} journals here; expected one", dir.string(), found.size()));
  return found.front();
}

// The q-quantile of sorted values (nearest rank).
double quantile(const std::vector<double>& sorted, double q) {
  const auto i = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size()))) - 1;
  return sorted[std::min(i, sorted.size() - 1)];
}

std::string utc(std::int64_t t) {
  const std::time_t tt = static_cast<std::time_t>(t);
  std::tm tm{};
  gmtime_r(&tt, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%d %H:%M", &tm);
  return buf;
}

std::string count(double n) {
  if (n >= 1e9) return fmt::format("{:.2f} G", n / 1e9);
  if (n >= 1e6) return fmt::format("{:.1f} M", n / 1e6);
  return fmt::format("{:.0f}", n);
}

struct Totals {
  double core_seconds = 0.0, star_seconds = 0.0, traced = 0.0, reused = 0.0;
  long frames = 0;
};

}  // namespace

int run_cost(const CostCommand& cmd) {
  if (cmd.csv) require_extension(*cmd.csv, ".csv", "per-frame costs as CSV");
  std::string csv = "shot,frame,width,height,supersample,rays,reused,core_seconds,star_seconds,finished\n";
  Totals all;
  for (const auto& dir : cmd.dirs) {
    const auto path = journal_in(dir);
    const farm::JournalContents j = farm::read_journal(path);
    const std::string shot = path.stem().string();
    std::vector<std::pair<double, int>> per_frame;  // core-seconds, frame
    Totals t;
    long unrecorded = 0;
    std::int64_t first = 0, last = 0;
    for (const auto& [n, f] : j.frames) {
      const farm::FrameCost& c = f.cost;
      if (!c.recorded()) {
        ++unrecorded;
        continue;
      }
      per_frame.emplace_back(c.core_seconds, n);
      t.core_seconds += c.core_seconds;
      t.star_seconds += c.star_seconds;
      t.traced += static_cast<double>(c.rays);
      t.reused += static_cast<double>(c.reused);
      ++t.frames;
      first = first == 0 ? c.finished : std::min(first, c.finished);
      last = std::max(last, c.finished);
      csv += fmt::format("{},{},{},{},{},{},{},{:.3f},{:.3f},{}\n", shot, n, f.settings.width, f.settings.height,
                         f.settings.supersample, c.rays, c.reused, c.core_seconds, c.star_seconds, c.finished);
    }
    fmt::print("{} ({}): {} frames in the journal", shot, dir.string(), j.frames.size());
    if (j.last_frame >= 0) fmt::print(", the latest at {}", j.frames.at(j.last_frame).settings.describe());
    fmt::print("\n");
    if (unrecorded > 0)
      fmt::print("  {} frames without a recorded cost (rendered by a lightcone that did not record it)\n", unrecorded);
    if (t.frames == 0) continue;
    std::sort(per_frame.begin(), per_frame.end());
    std::vector<double> seconds;
    for (const auto& p : per_frame) seconds.push_back(p.first);
    fmt::print("  compute: {:.1f} core-seconds ({:.2f} core-hours), point stars {:.1f} s more on the writer\n",
               t.core_seconds, t.core_seconds / 3600.0, t.star_seconds);
    fmt::print("  per frame, core-seconds: mean {:.2f}, median {:.2f}, p90 {:.2f}, fastest {:.2f} (frame {}), "
               "slowest {:.2f} (frame {})\n",
               t.core_seconds / static_cast<double>(t.frames), quantile(seconds, 0.5), quantile(seconds, 0.9),
               per_frame.front().first, per_frame.front().second, per_frame.back().first, per_frame.back().second);
    fmt::print("  samples: {} traced, {} reused ({:.0f}% of all)\n", count(t.traced), count(t.reused),
               100.0 * t.reused / std::max(1.0, t.traced + t.reused));
    fmt::print("  stored from {} to {} UTC\n", utc(first), utc(last));
    all.core_seconds += t.core_seconds;
    all.star_seconds += t.star_seconds;
    all.traced += t.traced;
    all.reused += t.reused;
    all.frames += t.frames;
  }
  if (cmd.dirs.size() > 1 && all.frames > 0)
    fmt::print("all: {} frames, {:.0f} core-seconds ({:.2f} core-hours; {:.2f} h on 2 cores), {} samples traced, {} "
               "reused\n",
               all.frames, all.core_seconds, all.core_seconds / 3600.0, all.core_seconds / 7200.0, count(all.traced),
               count(all.reused));
  if (cmd.csv) {
    write_output(cmd.csv, csv);
    fmt::print("per-frame costs: {}\n", cmd.csv->string());
  }
  return 0;
}

}  // namespace lc
