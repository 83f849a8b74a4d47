#include "render_job.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include <fmt/format.h>

#include "job/shot_survey.hpp"
#include "job/test_pause.hpp"
#include "image_size.hpp"

namespace lc {


namespace {

// The command line's shutter (docs/motion_blur.md).  Throws
// std::invalid_argument naming the flag.
ShutterOverride shutter_override(std::optional<double> open, const std::optional<std::string>& position,
                                 std::optional<int> time_samples) {
  ShutterOverride out;
  if (open) {
    if (!(*open >= 0.0 && *open <= 1.0))
      throw std::invalid_argument(fmt::format(
          "--shutter {}: must be between 0 (closed) and 1 (open for the whole frame interval); 0.5 is the film "
          "camera's 180 degrees",
          *open));
    out.open = *open;
  }
  if (position) {
    const auto names = choice_names(ShutterPosition{});
    const auto it = std::find(names.begin(), names.end(), *position);
    if (it == names.end())
      throw std::invalid_argument(
          fmt::format("--shutter-position {}: expected {}", *position, choices_text<ShutterPosition>()));
    out.position = static_cast<ShutterPosition>(it - names.begin());
  }
  if (time_samples) {
    if (*time_samples < 1 || *time_samples > max_time_samples)
      throw std::invalid_argument(fmt::format(
          "--time-samples {}: must be between 1 and {} (each is an evaluation of the shot and a scene held while the "
          "frame renders)",
          *time_samples, max_time_samples));
    out.time_samples = *time_samples;
  }
  return out;
}

}  // namespace

RenderJob load_render_job(const RenderRequest& cmd) {
  RenderJob job;
  if (cmd.stripes && (*cmd.stripes < 1 || *cmd.stripes > 16384))
    throw std::invalid_argument(fmt::format("--stripes {}: must be between 1 and 16384", *cmd.stripes));
  if (!(cmd.progress >= 0) || !std::isfinite(cmd.progress))
    throw std::invalid_argument(fmt::format("--progress {}: must be 0 (off) or a number of seconds", cmd.progress));
  job.test_pause = farm::test_pause_after();
  job.delivery = delivery_from_flags(cmd.delivery);  // (before the shot: a bad flag is said first)
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
  job.shot->set_delivery(job.delivery);
  job.shutter = shutter_override(cmd.shutter, cmd.shutter_position, cmd.time_samples);
  job.shot->set_shutter(job.shutter);
  const auto [shot_width, shot_height] = delivery_size(job.delivery.camera, info.width, info.height);
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
