#include "stages/pausing_stripe_renderer.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <thread>

#include <fmt/format.h>

namespace lc::farm {

PausingStripeRenderer::PausingStripeRenderer(StripeRenderer& inner, long sets, std::string who,
                                             std::function<bool()> release)
    : inner_(inner), sets_(sets), who_(std::move(who)), release_(std::move(release)) {}

RenderStats PausingStripeRenderer::render(const WorkItem& item, FrameImage& canvas) {
  // Sets are counted as they start, so exactly `sets_` of them run before
  // the pause; a held set is rendered for real once released.
  if (started_.fetch_add(1) >= sets_) {
    std::call_once(said_, [&] {
      fmt::print(stderr, "render: test pause: pid {} ({}) holds its working sets after {}\n", ::getpid(), who_, sets_);
      std::fflush(stderr);
    });
    while (!stopped_ && !release_()) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return inner_.render(item, canvas);
}

std::unique_ptr<PausingStripeRenderer> paused_for_a_test(StripeRenderer& renderer, std::optional<long> sets,
                                                         const std::string& who, std::function<bool()> released) {
  if (!sets) return nullptr;
  return std::make_unique<PausingStripeRenderer>(renderer, *sets, who, std::move(released));
}

}  // namespace lc::farm
