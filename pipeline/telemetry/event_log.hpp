#pragma once
// The farm's event log: DIR/<shot>.events, what a render is doing as it
// happens, for `lightcone monitor` (docs/monitor.md; the lines are
// store/event_file.hpp's).  Only the render's master writes it, and nothing
// the render decides reads it: the journal is the record of finished
// frames, this is a view of the work.  So it is appended a line at a time
// (one write(2) with O_APPEND each) and never synced, and a failure to write
// it is a warning, not an error.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <filesystem>
#include <istream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "store/event_file.hpp"
#include "telemetry/run_progress.hpp"

namespace lc::farm {

// This process's command line, as Linux keeps it (/proc/self/cmdline);
// empty where it cannot be read.
std::vector<std::string> own_command_line();

class EventLog {
 public:
  // Opens DIR/<shot>.events for appending, creating it with its header.
  // Never throws: a log that cannot be opened, or is no regular file (a
  // link is never appended through, a FIFO never waited on), is said once
  // on stderr and the methods do nothing.
  EventLog(const std::filesystem::path& dir, const std::string& shot);
  ~EventLog();
  EventLog(const EventLog&) = delete;
  EventLog& operator=(const EventLog&) = delete;

  void run_started(const RunStart& run);
  void rank_joined(int rank, const std::string& host, int threads);
  // A worker did not answer the master's stop in time: it was killed or its
  // node failed (docs/monitor.md).
  void rank_lost(int rank, const std::string& host);
  // `open`: the frames in flight; `held`: what each MPI worker holds (none
  // for a local farm).
  void progress(const RunProgress& p, const std::vector<int>& open, const std::vector<RankHolding>* held = nullptr);
  void frame_stored(int frame, double core_seconds, long rays);
  void error(const std::string& message);
  // The run's last line.  A log this run created for a run that stored no
  // frame is removed instead: a failed render leaves its folder as it
  // found it (it leaves no journal either), and says its error on stderr.
  void run_ended(const char* status, int stored);

 private:
  void append(const std::string& content);
  std::mutex mutex_;
  int fd_ = -1;
  std::string name_;
  bool warned_ = false;
  bool created_ = false;  // this run made the file
};

// Writes a run's progress to the log every `interval` from a thread of its
// own while alive, and once more when destroyed: what a monitor shows of
// the frames in flight and the rays traced between frames.  `read` is
// called on that thread and must be thread-safe (the work queue's and the
// rank board's readers are).
class ProgressEvents {
 public:
  ProgressEvents(EventLog& log, std::function<ProgressReading()> read,
                 std::chrono::milliseconds interval = std::chrono::seconds(2));
  ~ProgressEvents();
  ProgressEvents(const ProgressEvents&) = delete;
  ProgressEvents& operator=(const ProgressEvents&) = delete;

 private:
  void write();
  EventLog& log_;
  std::function<ProgressReading()> read_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace lc::farm
