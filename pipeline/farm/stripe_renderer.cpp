#include "farm/stripe_renderer.hpp"

namespace lc::farm {

RenderStats SceneStripeRenderer::render(const WorkItem& item, FrameImage& canvas) {
  const auto scene = scenes_.get(item.frame);
  const std::vector<int> rows = layout_.rows(item.stripe);
  return render_rows(*scene, rs_, rows, canvas, memo_.get());
}

}  // namespace lc::farm
