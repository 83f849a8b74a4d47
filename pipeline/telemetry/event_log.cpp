#include "telemetry/event_log.hpp"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <istream>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fmt/format.h>

#include "store/durable_file.hpp"
#include "store/checked_line.hpp"

namespace lc::farm {

namespace fs = std::filesystem;

namespace {

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

}  // namespace

EventLog::EventLog(const fs::path& dir, const std::string& shot) : name_(events_file(dir, shot).string()) {
  // Opened as lightcone's own file: a link under its name is not appended
  // through, a FIFO does not block the render (which holds the folder's
  // lock); either is said and the render goes on without a log.
  OwnFile own;
  try {
    own = open_own_file(name_, O_WRONLY | O_APPEND | O_CREAT, "write the event log");
  } catch (const std::runtime_error& e) {
    fmt::print(stderr, "render: warning: {}: `lightcone monitor` will not see this run\n", e.what());
    warned_ = true;
    return;
  }
  fd_ = own.fd;
  created_ = own.created;
  struct stat st {};
  if (::fstat(fd_, &st) == 0 && st.st_size == 0) append(std::string(events_header));
}

EventLog::~EventLog() {
  if (fd_ >= 0) ::close(fd_);
}

void EventLog::append(const std::string& content) {
  if (fd_ < 0) return;
  const std::string line = with_check(content) + "\n";
  std::lock_guard lock(mutex_);
  // One write: with O_APPEND the line lands whole after whatever is there.
  const ssize_t n = ::write(fd_, line.data(), line.size());
  if (n != static_cast<ssize_t>(line.size()) && !warned_) {
    warned_ = true;
    fmt::print(stderr, "render: warning: cannot write the event log {} ({}); the render goes on\n", name_,
               n < 0 ? std::strerror(errno) : "a short write");
  }
}

namespace {

// The run line's cwd and command fields (" cwd=... command=..."), "" when
// the command line is unknown or too long.
std::string resume_fields(const RunStart& r) {
  if (r.command.empty()) return "";
  std::string joined;
  for (std::size_t k = 0; k < r.command.size(); ++k) joined += (k ? std::string(1, '\0') : "") + r.command[k];
  std::string fields = fmt::format(" cwd={} command={}", percent_encode(r.cwd), percent_encode(joined));
  // A command line so long that the run line would pass what a reader
  // takes is left out: the run line matters more.
  return fields.size() > max_event_line / 2 ? "" : fields;
}

}  // namespace

std::vector<std::string> own_command_line() {
  // NUL-terminated arguments; bounded, as Linux bounds a command line.
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::vector<std::string> out;
  std::size_t bytes = 0;
  for (std::string arg; std::getline(in, arg, '\0') && bytes < (1u << 20);) {
    bytes += arg.size() + 1;
    out.push_back(std::move(arg));
  }
  return out;
}

void EventLog::run_started(const RunStart& r) {
  append(fmt::format("t={:.3f} event=run pid={} host={} ranks={} threads={} todo={} done={} size={}x{} script={}{}",
                     now_seconds(), r.pid, percent_encode(r.host), r.ranks, r.threads, r.todo, r.done_before, r.width,
                     r.height, percent_encode(r.script), resume_fields(r)));
}

void EventLog::rank_joined(int rank, const std::string& host, int threads) {
  append(fmt::format("t={:.3f} event=rank rank={} host={} threads={}", now_seconds(), rank, percent_encode(host), threads));
}

void EventLog::rank_lost(int rank, const std::string& host) {
  append(fmt::format("t={:.3f} event=lost rank={} host={}", now_seconds(), rank, percent_encode(host)));
}

void EventLog::progress(const RunProgress& p, const std::vector<int>& open, const std::vector<RankHolding>* held) {
  std::string frames;
  for (std::size_t k = 0; k < open.size() && k < 64; ++k) frames += (k ? "," : "") + std::to_string(open[k]);
  std::string holding;
  if (held) {
    bool complete = true;
    holding = " held=" + format_holdings(*held, 8192, &complete);
    if (!complete) holding += " held_all=0";
  }
  append(fmt::format("t={:.3f} event=progress stored={} total={} rows={}/{} rays={} core_seconds={:.3f} open={}{}",
                     now_seconds(), p.frames_stored, p.frames_total, p.rows_done, p.rows_total, p.stats.rays,
                     p.stats.seconds, frames, holding));
}

void EventLog::frame_stored(int frame, double core_seconds, long rays) {
  append(fmt::format("t={:.3f} event=frame frame={} core_seconds={:.3f} rays={}", now_seconds(), frame, core_seconds, rays));
}

void EventLog::error(const std::string& message) {
  append(fmt::format("t={:.3f} event=error message={}", now_seconds(), percent_encode(message)));
}

void EventLog::run_ended(const char* status, int stored) {
  if (created_ && stored == 0 && fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
    ::unlink(name_.c_str());
    return;
  }
  append(fmt::format("t={:.3f} event=end status={} stored={}", now_seconds(), status, stored));
}

ProgressEvents::ProgressEvents(EventLog& log, std::function<ProgressReading()> read,
                               std::chrono::milliseconds interval)
    : log_(log), read_(std::move(read)) {
  thread_ = std::thread([this, interval] {
    std::unique_lock lock(mutex_);
    while (!stop_.wait_for(lock, interval, [this] { return stopping_; })) write();
  });
}

void ProgressEvents::write() {
  const ProgressReading r = read_();
  log_.progress(r.progress, r.open, r.held ? &*r.held : nullptr);
}

ProgressEvents::~ProgressEvents() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_.notify_all();
  thread_.join();
  write();
}

}  // namespace lc::farm
