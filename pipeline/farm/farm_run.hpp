#pragma once
// The master's side of a run, shared by the local farm and the MPI master:
// finished working sets go into the queue; completed frames go to a writer
// thread (so encoding and fsyncing a frame never keeps workers waiting);
// the first error stops everything.

#include <condition_variable>
#include <deque>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "farm/work_queue.hpp"

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
  // workers needs more than one).
  FarmRun(WorkQueue& queue, FrameSink& sink, int writers = 1);
  ~FarmRun();  // close()s
  FarmRun(const FarmRun&) = delete;
  FarmRun& operator=(const FarmRun&) = delete;

  // A handed-out set is rendered (its rows are in queue.canvas(item)).
  // Completed frames are queued for the writer.
  void finish(const WorkItem& item, const RenderStats& stats);
  // Records the first error and stops the queue; later errors are dropped.
  void fail(const std::string& message);
  std::optional<std::string> error() const;
  // Every frame stored, or an error recorded.
  bool over() const;
  // Waits until something changes (a frame stored, an error) or `timeout`.
  void wait(std::chrono::milliseconds timeout);
  // Lets the writer store what it holds (unless it failed itself), then
  // joins it.
  void close();

 private:
  void writer_loop();

  WorkQueue& queue_;
  FrameSink& sink_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<CompletedFrame> pending_;
  std::optional<std::string> error_;
  bool closing_ = false, writer_failed_ = false;
  std::vector<std::thread> writers_;
};

}  // namespace lc::farm
