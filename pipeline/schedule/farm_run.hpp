#pragma once
// The master's side of a run, shared by the local farm and the MPI master:
// finished working sets go into the queue; completed frames go to a writer
// thread (so encoding and fsyncing a frame never keeps workers waiting);
// the first error stops everything.

#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "schedule/work_queue.hpp"

namespace lc::farm {

// Where completed frames go (the frame store, or nowhere in a benchmark).
class FrameSink {
 public:
  virtual ~FrameSink() = default;
  // Called on the writer threads, each with a different frame (so
  // concurrently when there are several); throws on failure.
  virtual void store(const CompletedFrame& frame) = 0;
};

// Writer threads of an MPI master (docs/cluster.md: one writes ~4 frames/s
// of 1280x720, which feeds a few hundred cores at today's ray speed).
inline constexpr int master_writer_threads = 4;

class FarmRun {
 public:
  // `writers` threads store frames in parallel (encoding and syncing a
  // frame takes a quarter of a second at 1280x720: a master feeding many
  // workers needs more than one).  `signal_received` (may be empty) says
  // which signal asked the run to stop (0: none); over() and wait() look.
  FarmRun(WorkQueue& queue, FrameSink& sink, int writers = 1, std::function<int()> signal_received = {});
  ~FarmRun();  // close()s
  FarmRun(const FarmRun&) = delete;
  FarmRun& operator=(const FarmRun&) = delete;

  // A handed-out set is rendered (its rows are in queue.canvas(item)), by
  // `rank` on `node` (WorkQueue::finish).  Completed frames are queued for
  // the writer.
  void finish(const WorkItem& item, const RenderStats& stats, int rank = 0, std::string_view node = {});
  // Records the first error and stops the queue; later errors are dropped.
  void fail(const std::string& message);
  std::optional<std::string> error() const;
  // Stops the queue because a user asked (Ctrl-C, kill; here or on a
  // worker): no more sets are handed out, the frames complete are still
  // stored (close()), and it is not an error.  The first signal is kept.
  void interrupt(int signal);
  // The signal that stopped the run, 0 if none.
  int interrupted() const;
  // Every frame stored, or an error or interruption recorded.  Notices a
  // signal first.
  bool over();
  // Waits until something changes (a frame stored, an error) or `timeout`,
  // then notices a signal.
  void wait(std::chrono::milliseconds timeout);
  // Lets the writer store what it holds (unless it failed itself), then
  // joins it.
  void close();

 private:
  void writer_loop();
  void notice_signal();

  WorkQueue& queue_;
  FrameSink& sink_;
  std::function<int()> signal_received_;
  int interrupted_ = 0;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<CompletedFrame> pending_;
  std::optional<std::string> error_;
  bool closing_ = false, writer_failed_ = false;
  std::vector<std::thread> writers_;
};

}  // namespace lc::farm
