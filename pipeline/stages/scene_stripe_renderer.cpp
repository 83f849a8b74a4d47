#include "stages/scene_stripe_renderer.hpp"

#include "render/renderer.hpp"

#include "core/cpu_time.hpp"

namespace lc::farm {

RenderStats SceneStripeRenderer::render(const WorkItem& item, FrameImage& canvas) {
  // CPU time, not wall time: what the set cost however busy the machine was.
  const double start = thread_cpu_seconds();
  const auto scene = scenes_.get(item.frame);
  const std::vector<int> rows = layout_.rows(item.stripe);
  {
    // The frame's first set makes room for its sky points; threads
    // rendering other sets of the frame wait for that.
    std::lock_guard lock(prepare_mutex_);
    prepare_frame(*scene, canvas);
  }
  RenderStats stats = render_rows(*scene, rs_, rows, canvas, memo_.get());
  stats.seconds = thread_cpu_seconds() - start;
  return stats;
}

}  // namespace lc::farm
