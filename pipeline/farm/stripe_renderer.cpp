#include "farm/stripe_renderer.hpp"

#include <unistd.h>

#include <charconv>
#include <ctime>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string_view>
#include <thread>

#include <fmt/format.h>

#include "core/thread_clock.hpp"

namespace lc::farm {

RenderStats SceneStripeRenderer::render(const WorkItem& item, FrameImage& canvas) {
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

std::optional<long> test_pause_after() {
  const char* text = std::getenv("LIGHTCONE_TEST_PAUSE_AFTER");
  if (!text || !*text) return std::nullopt;
  const std::string_view v(text);
  long sets = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), sets);
  if (ec != std::errc() || end != v.data() + v.size() || sets < 0)
    throw std::invalid_argument(
        fmt::format("LIGHTCONE_TEST_PAUSE_AFTER={}: expected a number of working sets (a test hook)", v));
  return sets;
}

}  // namespace lc::farm
