#pragma once
// The farm's event log: DIR/<shot>.events, what a render is doing as it
// happens, for `lightcone monitor` (docs/monitor.md).  Only the render's
// master writes it, and nothing the render decides reads it: the journal
// is the record of finished frames, this is a view of the work.  So it is
// appended a line at a time (one write(2) with O_APPEND each) and never
// synced, and a failure to write it is a warning, not an error.  Each line
// carries its check (checked_line.hpp): one cut short by a crash, or being
// written while a monitor reads, is skipped.  Lines:
//   lightcone-events 1
//   t=<unix s> event=run pid=<n> host=<name> ranks=<n> threads=<n> todo=<n> done=<n> size=<W>x<H> script=<path>
//              [cwd=<path> command=<argv joined by NUL>]            (what resumes the run)
//   t=<unix s> event=rank rank=<n> host=<name> threads=<n>          (an MPI worker joined)
//   t=<unix s> event=progress stored=<n> total=<n> rows=<done>/<all> rays=<n> core_seconds=<s> open=<f>,<f>,...
//              [held=<rank>:<sets>:<f>+<f>...,... [held_all=0]]      (an MPI farm: the workers holding sets;
//                                                                     held_all=0: more than fitted in 8 KiB)
//   t=<unix s> event=lost rank=<n> host=<name>                      (a worker that stopped answering)
//   t=<unix s> event=frame frame=<n> core_seconds=<s> rays=<n>       (a frame stored)
//   t=<unix s> event=error message=<percent-encoded text>
//   t=<unix s> event=end status=<done|interrupted|error> stored=<n>
// A run's lines follow its `run` line; a later `run` starts the next run.

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <istream>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "transport/rank_board.hpp"
#include "schedule/work_queue.hpp"

namespace lc::farm {

// What a run's `run` line says.
struct RunStart {
  double time = 0.0;
  long pid = 0;
  std::string host;
  int ranks = 1, threads = 0;
  int todo = 0, done_before = 0;
  int width = 0, height = 0;
  std::string script;  // the shot script, absolute (the monitor's pixel inspector traces with it)
  // The render's command line (its argv) and the folder it ran in: what
  // resumes it, shown by the monitor to copy.  Empty in older logs.
  std::vector<std::string> command;
  std::string cwd;
};

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
  // `open`: the frames in flight (WorkQueue::open_frames); `held`: what
  // each MPI worker holds (none for a local farm).
  void progress(const QueueProgress& p, const std::vector<int>& open, const std::vector<RankHolding>* held = nullptr);
  void frame_stored(int frame, double core_seconds, long rays);
  void error(const std::string& message);
  // The run's last line.  A log this run created for a run that stored no
  // frame is removed instead: a failed render leaves its folder as it
  // found it (it leaves no journal either), and says its error on stderr.
  void run_ended(const char* status, int stored);

  // The file's name: DIR/<shot>.events.
  static std::filesystem::path file_of(const std::filesystem::path& dir, const std::string& shot);

 private:
  void append(const std::string& content);
  std::mutex mutex_;
  int fd_ = -1;
  std::string name_;
  bool warned_ = false;
  bool created_ = false;  // this run made the file
};

// Writes the queue's progress (and the board's holdings, for an MPI farm)
// to the log every `interval` from a thread of its own while alive, and
// once more when destroyed: what a monitor shows of the frames in flight
// and the rays traced between frames.
class ProgressEvents {
 public:
  ProgressEvents(EventLog& log, const WorkQueue& queue, const RankBoard* board = nullptr,
                 std::chrono::milliseconds interval = std::chrono::seconds(2));
  ~ProgressEvents();
  ProgressEvents(const ProgressEvents&) = delete;
  ProgressEvents& operator=(const ProgressEvents&) = delete;

 private:
  void write();
  EventLog& log_;
  const WorkQueue& queue_;
  const RankBoard* board_;
  std::mutex mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

// One event as read back.
struct Event {
  double time = 0.0;
  std::string kind;                           // run, rank, progress, frame, lost, error, end
  std::map<std::string, std::string> fields;  // the rest, decoded
};

// The most workers (rank lines) and lost workers a summary holds.
inline constexpr std::size_t max_summary_ranks = 4096;

// What a monitor needs of an event log: the latest run and what happened
// in it.  Read a line at a time in bounded memory (a 100,000-frame film's
// log is read whole, but only the latest run's ranks, last progress and the
// last `keep` events are held).
struct EventSummary {
  std::optional<RunStart> run;              // the latest run, if any
  std::vector<Event> ranks;                 // its workers
  std::vector<int> lost;                    // its workers given up as lost
  std::optional<Event> progress;            // its latest progress line
  std::optional<Event> end;                 // how it ended, if it has
  std::deque<Event> recent;                 // its last `keep` events, oldest first
  std::vector<Event> errors;                // its errors (at most `keep`)
  int frames_stored = 0;                    // its frame lines
  int bad_lines = 0;                        // lines that failed their check or did not parse
};
// A log that is missing, or no regular file (a link, a FIFO), reads as
// an empty summary.
EventSummary read_events(const std::filesystem::path& file, std::size_t keep = 200);
// The same of a log's text (or of the lines appended to it since a read).
EventSummary read_events(std::istream& in, std::size_t keep = 200);

}  // namespace lc::farm
