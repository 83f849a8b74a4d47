#pragma once
// A render job: what every rank of `lightcone render` (the local farm's one
// process, an MPI master and each worker alike) derives from the command's
// flags and the shot script before any frame is rendered.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "job/stripes.hpp"
#include "frame_range.hpp"
#include "render/renderer.hpp"
#include "job/render_request.hpp"
#include "camera/delivery.hpp"
#include "script/shot.hpp"

namespace lc {

struct RenderJob {
  std::unique_ptr<Shot> shot;
  RenderSettings rs;
  std::vector<int> frames;          // to render, ascending
  std::optional<FrameRange> range;  // from --frames
  farm::StripeLayout layout{1, 1};
  int preview = 0;                  // --preview
  std::uint64_t digest = 0;         // farm::job_digest: what an MPI master and its workers compare
  Delivery delivery{};                             // --camera ... --sky
  ShutterOverride shutter{};                       // --shutter, --shutter-position, --time-samples
  std::optional<long> test_pause;   // LIGHTCONE_TEST_PAUSE_AFTER (job/test_pause.hpp)
};

// Loads the shot, checks the flags and reads the test hook.  Throws
// std::invalid_argument naming the flag (or the hook's variable), or the
// script's own error.
RenderJob load_render_job(const RenderRequest& cmd);

}  // namespace lc
