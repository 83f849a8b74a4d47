#pragma once
// The stripe renderer that traces rays: a working set's rows through the
// frame's scene (from the scene cache), with the sample memo.

#include <memory>
#include <mutex>

#include "stages/scene_cache.hpp"
#include "job/stripes.hpp"
#include "stages/stripe_renderer.hpp"
#include "render/sample_memo.hpp"

namespace lc::farm {

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

}  // namespace lc::farm
