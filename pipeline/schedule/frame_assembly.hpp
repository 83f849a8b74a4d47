#pragma once
// The frames being made: a canvas for each open frame, the stripes that
// have come back into it, who rendered them, and the run's progress counts.
// A frame is complete when its last stripe arrives, and leaves once the
// writer has stored it.  Not thread-safe: the work queue
// (schedule/work_queue.hpp) holds it under its lock.

#include <chrono>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "job/stripes.hpp"
#include "render/render_settings.hpp"
#include "schedule/work_item.hpp"
#include "store/frame_makers.hpp"
#include "telemetry/run_progress.hpp"

namespace lc::farm {

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

class FrameAssembly {
 public:
  // Frames of `rs` cut as `layout`; the run's totals count `frames` frames
  // and, if `preview_stripes` is not empty, a preview of each.
  FrameAssembly(RenderSettings rs, const StripeLayout& layout, int frames, const std::vector<int>& preview_stripes);

  // A frame's first set is out: it gets a canvas and takes a slot until
  // stored(); it is complete when `stripes` sets have come back.
  void open(Pass pass, int frame, int stripes);
  // Where the rows of a set of an open frame go (stable until it completes);
  // throws std::logic_error for a frame that has no canvas.
  FrameImage& canvas(Pass pass, int frame);
  // Set `item` (its stripe the `index`-th of its pass's, -1 if none) came
  // back, rendered by `rank` on `node`.  Returns the frame when this was its
  // last stripe, with the ranks that rendered it (those that rendered the
  // most sets, if more than max_listed_ranks).  Throws std::logic_error for
  // a set that is not out (a duplicate, another frame's, a bad index).
  std::optional<CompletedFrame> finish(const WorkItem& item, int index, const RenderStats& stats, int rank,
                                       std::string_view node);
  // The writer has stored a completed frame: it frees its slot.  Throws
  // std::logic_error for a frame not complete.
  void stored(Pass pass, int frame);

  // Frames open: handed out and not yet stored.
  int open_count() const { return static_cast<int>(open_.size()); }
  // The frames of the full pass open, ascending.
  std::vector<int> open_frames() const;
  const RunProgress& progress() const { return progress_; }
  const RenderSettings& settings() const { return rs_; }

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

  RenderSettings rs_;
  StripeLayout layout_;
  std::map<Key, OpenFrame> open_;
  RunProgress progress_;
};

}  // namespace lc::farm
