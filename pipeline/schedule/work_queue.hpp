#pragma once
// The queue of working sets (one stripe of one frame) over every frame of a
// job: the joint of the hand-out order (schedule/hand_out.hpp) and the
// assembly of finished stripes into frames (schedule/frame_assembly.hpp)
// under one lock, with the one rule that needs both, the limit on open
// frames.  Whoever is idle — a local thread or, through the MPI master, a
// worker rank — takes the next set.  Thread-safe.

#include <condition_variable>
#include <mutex>
#include <optional>
#include <string_view>
#include <vector>

#include "job/stripes.hpp"
#include "render/render_settings.hpp"
#include "schedule/frame_assembly.hpp"
#include "schedule/hand_out.hpp"
#include "schedule/work_item.hpp"
#include "telemetry/run_progress.hpp"

namespace lc::farm {

class WorkQueue {
 public:
  struct Options {
    int preview_every = 0;    // k >= 2: a preview pass of every k-th stripe first; 0: none
    int max_open_frames = 4;  // frames handed out but not yet stored (bounds memory)
  };

  // Frames in the order they are to be rendered.
  WorkQueue(RenderSettings rs, StripeLayout layout, std::vector<int> frames, Options options);

  // The next working set, or nullopt when none can be handed out now: every
  // set is out (see drained()), the queue was stopped, or max_open_frames
  // frames await their stripes or their writer (try again after stored()).
  std::optional<WorkItem> take();
  // take() for a taker that keeps something between frames (an MPI worker
  // with its sample memo, numbered >= 0): of the current frame's stripes,
  // those this taker had last time first, then any nobody had, then the
  // others in order.  A still scene's rows then go back to the worker that
  // kept their samples.
  std::optional<WorkItem> take_for(int taker);
  // Like take() but waits while throttled; nullopt once drained or stopped.
  std::optional<WorkItem> take_wait();
  bool drained() const;

  // Where the rows of a handed-out set go (stable until its frame completes).
  FrameImage& canvas(const WorkItem& item);
  // Marks a handed-out set done, rendered by `rank` on `node` (a local
  // farm's threads: rank 0 on this host).  Returns the frame when this was
  // its last stripe, with the ranks that rendered it (those that rendered
  // the most sets, if more than max_listed_ranks).  Throws std::logic_error
  // for a set that is not out (a duplicate).
  std::optional<CompletedFrame> finish(const WorkItem& item, const RenderStats& stats, int rank = 0,
                                       std::string_view node = {});
  // The writer has stored a completed frame: frees its slot.
  void stored(Pass pass, int frame);
  // Every frame of both passes completed and stored.
  bool all_stored() const;

  // Changes the limit of open frames (the MPI master learns how many
  // threads it feeds only as workers say hello).
  void set_max_open_frames(int n);

  // Makes take() return nullopt from now on and wakes take_wait().
  void stop();
  bool stopped() const;

  RunProgress progress() const;
  // The frames of the full pass handed out and not yet stored, ascending.
  std::vector<int> open_frames() const;
  const StripeLayout& layout() const { return hand_out_.layout(); }
  const RenderSettings& settings() const { return assembly_.settings(); }
  // The stripes a frame of `pass` consists of.
  const std::vector<int>& stripes_of(Pass pass) const { return hand_out_.stripes_of(pass); }

 private:
  // The next set for `taker` (-1: in order), opening its frame if it is the
  // first; nullopt when stopped, drained or throttled.
  std::optional<WorkItem> take_locked(int taker);

  Options options_;
  mutable std::mutex mutex_;
  std::condition_variable slot_freed_;
  HandOut hand_out_;
  FrameAssembly assembly_;
  bool stopped_ = false;
};

// Frames open at once for `threads` render threads (each with one set in
// reserve) on frames of `stripes` stripes: enough that no thread waits
// while the last frames are assembled and written, few enough to bound
// memory.
int open_frames_for(int threads, int stripes);

}  // namespace lc::farm
