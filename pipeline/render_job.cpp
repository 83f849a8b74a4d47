#include "render_job.hpp"

#include <cmath>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>

#include "farm/shot_inputs.hpp"
#include "farm/test_pause.hpp"
#include "image_size.hpp"

namespace lc {


RenderJob load_render_job(const RenderCommand& cmd) {
  RenderJob job;
  if (cmd.stripes && (*cmd.stripes < 1 || *cmd.stripes > 16384))
    throw std::invalid_argument(fmt::format("--stripes {}: must be between 1 and 16384", *cmd.stripes));
  if (!(cmd.progress >= 0) || !std::isfinite(cmd.progress))
    throw std::invalid_argument(fmt::format("--progress {}: must be 0 (off) or a number of seconds", cmd.progress));
  job.test_pause = farm::test_pause_after();
  job.shot = std::make_unique<Shot>(cmd.shot);
  const ShotInfo& info = job.shot->info();
  if (!cmd.frame_list.empty()) {
    job.frames = cmd.frame_list;
    for (std::size_t k = 0; k < job.frames.size(); ++k)
      if (job.frames[k] < 0 || job.frames[k] >= info.frames || (k > 0 && job.frames[k] <= job.frames[k - 1]))
        throw std::invalid_argument(fmt::format("frame list: frame {} is out of order or outside the shot's 0-{}",
                                                job.frames[k], info.frames - 1));
  } else {
    job.range = cmd.frames ? parse_frame_range(*cmd.frames, info.frames, "--frames") : all_frames(info.frames);
    job.frames = job.range->frames();
  }
  const auto delivery = delivery_named(cmd.camera);
  if (!delivery) throw std::invalid_argument(fmt::format("--camera {}: expected shot, dome or 360", cmd.camera));
  job.delivery = *delivery;
  job.shot->set_delivery(job.delivery);
  const auto [shot_width, shot_height] = delivery_size(job.delivery, info.width, info.height);
  std::tie(job.rs.width, job.rs.height) = output_size(shot_width, shot_height, cmd.size, cmd.scale);
  if (cmd.region) {
    const Region region = parse_region(*cmd.region, job.rs.width, job.rs.height);
    job.rs.window = region.window;
    job.rs.width = region.width;
    job.rs.height = region.height;
  }
  job.rs.supersample = cmd.supersample.value_or(info.supersample);
  if (job.rs.supersample < 1 || job.rs.supersample > 16)
    throw std::invalid_argument(fmt::format("--supersample {}: must be between 1 and 16", job.rs.supersample));
  job.rs.layers = cmd.layers;
  job.rs.adaptive = !cmd.full_supersample;
  job.layout = farm::StripeLayout(job.rs.height, cmd.stripes.value_or(farm::default_stripes));
  job.preview = cmd.preview;
  if (job.preview != 0 && (job.preview < 2 || job.preview > job.layout.stripes()))
    throw std::invalid_argument(fmt::format(
        "--preview {}: must be between 2 and the number of stripes ({}; see --stripes)", cmd.preview, job.layout.stripes()));
  job.digest = farm::job_digest(*job.shot, job.rs, job.layout.stripes(), job.preview);
  return job;
}

}  // namespace lc
