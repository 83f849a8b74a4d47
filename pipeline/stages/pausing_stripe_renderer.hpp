#pragma once
// The stage the test hook puts in front of a render's stripe renderer
// (job/test_pause.hpp says when): it holds working sets at a known count, so
// the e2e tests stop a render there however fast the machine is.

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "stages/stripe_renderer.hpp"

namespace lc::farm {

// Renders the first `sets` working sets of this process through `inner`,
// then holds every further one at its start until `release()` says so (or
// stop() is called), after saying once on standard error that it paused,
// with its pid and `who`.
class PausingStripeRenderer final : public StripeRenderer {
 public:
  PausingStripeRenderer(StripeRenderer& inner, long sets, std::string who, std::function<bool()> release);
  RenderStats render(const WorkItem& item, FrameImage& canvas) override;
  // Releases the held sets as release() would.
  void stop() override { stopped_ = true; }

 private:
  StripeRenderer& inner_;
  long sets_;
  std::string who_;
  std::function<bool()> release_;
  std::atomic<long> started_{0};
  std::atomic<bool> stopped_{false};
  std::once_flag said_;
};

// `renderer` wrapped in the pause when `sets` (test_pause_after()'s value)
// asks for one, else nullptr.  `released` ends the pause.
std::unique_ptr<PausingStripeRenderer> paused_for_a_test(StripeRenderer& renderer, std::optional<long> sets,
                                                         const std::string& who, std::function<bool()> released);

}  // namespace lc::farm
