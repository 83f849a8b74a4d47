#pragma once
// What a worker does with a working set: render its rows into a full-size
// canvas.  The real one traces rays through the frame's scene; the farm
// benchmark's does nothing, to time the farm alone.

#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "farm/scene_cache.hpp"
#include "farm/work_queue.hpp"
#include "render/sample_memo.hpp"

namespace lc::farm {

class StripeRenderer {
 public:
  virtual ~StripeRenderer() = default;
  // Fills the set's rows of `canvas` (make_frame-sized); thread-safe for
  // sets with disjoint rows.  Throws for a scene that cannot be built.
  virtual RenderStats render(const WorkItem& item, FrameImage& canvas) = 0;
  // The run is ending (an MPI worker told to stop): a render() waiting for
  // something other than its rays should stop waiting.  Thread-safe.
  virtual void stop() {}
};

// With `reuse`, a row's samples that cannot change are kept for the later
// frames of the same still scene this process renders (SampleMemo).
class SceneStripeRenderer final : public StripeRenderer {
 public:
  SceneStripeRenderer(SceneCache& scenes, const RenderSettings& rs, const StripeLayout& layout, bool reuse)
      : scenes_(scenes), rs_(rs), layout_(layout), memo_(reuse ? std::make_unique<SampleMemo>(rs) : nullptr) {}
  RenderStats render(const WorkItem& item, FrameImage& canvas) override;

 private:
  SceneCache& scenes_;
  RenderSettings rs_;
  StripeLayout layout_;
  std::unique_ptr<SampleMemo> memo_;
  std::mutex prepare_mutex_;
};

// Leaves the rows as they are (zero): a working set that costs nothing.
class NullStripeRenderer final : public StripeRenderer {
 public:
  RenderStats render(const WorkItem&, FrameImage&) override { return {}; }
};

}  // namespace lc::farm
