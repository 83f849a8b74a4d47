#pragma once
// What a worker does with a working set: render its rows into a full-size
// canvas.  The real one (stages/scene_stripe_renderer.hpp) traces rays
// through the frame's scene; the farm benchmark's does nothing, to time the
// farm alone.  Without the scene, so the farm's loops build without the
// registries.

#include "render/render_settings.hpp"
#include "schedule/work_item.hpp"

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

// Leaves the rows as they are (zero): a working set that costs nothing.
class NullStripeRenderer final : public StripeRenderer {
 public:
  RenderStats render(const WorkItem&, FrameImage&) override { return {}; }
};

}  // namespace lc::farm
