#pragma once
// What a worker does with a working set: render its rows into a full-size
// canvas.  The real one traces rays through the frame's scene; the farm
// benchmark's does nothing, to time the farm alone.

#include <atomic>
#include <functional>
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

// A test hook (LIGHTCONE_TEST_PAUSE_AFTER, docs/cli.md; tests/e2e): renders
// the first `sets` working sets of this process through `inner`, then
// holds every further one at its start until `release()` says so (or
// stop() is called), after
// saying once on standard error that it paused, with its pid and `who`.
// A render paused at a known point can be killed or interrupted there by a
// test however fast or slow the machine is, instead of at a moment a
// sleep guessed.
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

// The number of working sets LIGHTCONE_TEST_PAUSE_AFTER asks a render to
// pause after, if it is set (a whole number >= 0; anything else throws
// std::invalid_argument naming the variable).
std::optional<long> test_pause_after();

// Leaves the rows as they are (zero): a working set that costs nothing.
class NullStripeRenderer final : public StripeRenderer {
 public:
  RenderStats render(const WorkItem&, FrameImage&) override { return {}; }
};

}  // namespace lc::farm
