#pragma once
// The queue of working sets (one stripe of one frame) over every frame of a
// job, and the assembly of finished stripes into frames.  Whoever is idle —
// a local thread or, through the MPI master, a worker rank — takes the next
// set.  Sets come out frame by frame, so only a few frames are open at once;
// with a preview pass, every k-th stripe of every frame comes first.
// Thread-safe.

#include <chrono>
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "store/frame_makers.hpp"
#include "job/stripes.hpp"
#include "render/render_settings.hpp"
#include "telemetry/run_progress.hpp"

namespace lc::farm {

enum class Pass { preview, full };

struct WorkItem {
  int frame = 0;
  int stripe = 0;
  Pass pass = Pass::full;
  bool operator==(const WorkItem&) const = default;
};

// A frame whose stripes have all arrived; the stripes of a preview are those
// with stripe % preview_every == 0, the other rows are zero.
struct CompletedFrame {
  Pass pass = Pass::full;
  int frame = 0;
  FrameImage image;
  RenderStats stats;
  FrameMakers makers;  // the ranks that rendered its sets, with their nodes
  std::chrono::steady_clock::time_point dispatched;  // when its first set was handed out
};

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
  const StripeLayout& layout() const { return layout_; }
  const RenderSettings& settings() const { return rs_; }
  // The stripes a frame of `pass` consists of.
  const std::vector<int>& stripes_of(Pass pass) const { return pass == Pass::preview ? preview_stripes_ : all_stripes_; }

 private:
  struct OpenFrame {
    std::unique_ptr<FrameImage> canvas;
    std::vector<char> done;  // per stripe index
    int remaining = 0;
    RenderStats stats;
    std::chrono::steady_clock::time_point opened;   // its first set handed out
    std::map<int, std::pair<std::string, int>> by;  // rank -> its node and the sets it rendered
  };
  using Key = std::pair<int, int>;  // (pass, frame)
  static Key key(Pass p, int frame) { return {static_cast<int>(p), frame}; }
  std::optional<WorkItem> take_locked(int taker);
  // The index (into the pass's stripes) of the current frame's next set for
  // `taker` (-1: in order).
  std::size_t pick_locked(int taker);

  RenderSettings rs_;
  StripeLayout layout_;
  std::vector<int> frames_;
  Options options_;
  std::vector<int> preview_stripes_, all_stripes_;

  mutable std::mutex mutex_;
  std::condition_variable slot_freed_;
  // Cursor: pass (0 preview, 1 full), index into frames_; within the frame
  // (open once its first set is out) the sets handed out so far.
  int cur_pass_ = 0;
  std::size_t cur_frame_ = 0;
  bool frame_started_ = false;
  std::vector<char> handed_;   // per index into the pass's stripes
  std::size_t handed_count_ = 0, lowest_ = 0;  // lowest_: no set below it is left
  std::vector<int> owner_;     // per stripe: the taker it went to last (-1: none)
  std::map<int, std::vector<std::size_t>> left_for_;  // per owner, the current frame's indices it had, descending
  std::map<Key, OpenFrame> open_;  // handed out and not stored yet
  bool stopped_ = false;
  RunProgress progress_;
};

// Frames open at once for `threads` render threads (each with one set in
// reserve) on frames of `stripes` stripes: enough that no thread waits
// while the last frames are assembled and written, few enough to bound
// memory.
int open_frames_for(int threads, int stripes);

}  // namespace lc::farm
