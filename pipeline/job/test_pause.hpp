#pragma once
// The one test hook in production code: LIGHTCONE_TEST_PAUSE_AFTER
// (docs/cli.md, "Environment"; docs/architecture.md, "Test hooks").  A
// render reads it once, when its job is loaded (render_job.cpp), and, when
// it is set, renders through a PausingStripeRenderer: the e2e tests stop a
// render at a known working set however fast the machine is, instead of at
// a moment a sleep guessed.  Nothing else in lightcone reads a test
// variable.

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "stages/stripe_renderer.hpp"

namespace lc::farm {

// The variable's name, for messages and the docs' test.
inline constexpr const char* test_pause_variable = "LIGHTCONE_TEST_PAUSE_AFTER";

// The number of working sets LIGHTCONE_TEST_PAUSE_AFTER asks a render to
// pause after, if it is set (a whole number >= 0; anything else throws
// std::invalid_argument naming the variable).
std::optional<long> test_pause_after();

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
