#include "stages/finish_frame.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include <fmt/format.h>

#include "render/point_star_stage.hpp"

namespace lc::farm {

FrameFinisher::FrameFinisher(std::string shot_name, double fps, const RenderSettings& rs,
                             std::vector<std::filesystem::path> asset_dirs, int star_threads)
    : shot_name_(std::move(shot_name)), fps_(fps), rs_(rs), resources_(std::move(asset_dirs)),
      star_threads_(std::max(1, star_threads)) {}

FinishedFrame FrameFinisher::finish(const CompletedFrame& cf, const FrameFacts& facts) {
  FinishedFrame out;
  const Camera camera(facts.camera, cf.image.width, cf.image.height, rs_.window);
  out.cost = {.rays = cf.stats.rays, .reused = cf.stats.reused, .core_seconds = cf.stats.seconds};
  // Its cost is CPU time, as the rays' is: the stage's threads share the
  // cores with the render threads, so wall time would count their waits.
  if (const auto stars = cf.image.sky.empty() ? std::nullopt : sky_point_stars(facts.sky, resources_)) {
    const auto start = std::chrono::steady_clock::now();
    FrameImage& with_stars = out.starred.emplace(
        FrameImage{cf.image.width, cf.image.height, cf.image.rgb, cf.image.layers, {}, cf.image.alpha});
    double cpu = 0.0;
    if (facts.instants.empty()) {
      draw_point_stars(*stars, camera, cf.image.sky, with_stars, star_threads_, &cpu);
    } else {
      // A blurred frame: each instant's stars through its own camera.
      std::vector<PointStars> instant_stars;
      std::vector<Camera> cameras;
      for (const FrameFacts::Instant& at : facts.instants) {
        const auto s = sky_point_stars(at.sky, resources_);
        if (!s)
          throw std::logic_error(fmt::format("frame {}: its sky has point stars at the frame's moment but not at "
                                             "every instant (Shot::frame_specs refuses a change of sky)",
                                             cf.frame));
        instant_stars.push_back(*s);
        cameras.emplace_back(at.camera, cf.image.width, cf.image.height, rs_.window);
      }
      std::vector<InstantStars> instants;
      for (std::size_t k = 0; k < cameras.size(); ++k) instants.push_back({&instant_stars[k], &cameras[k]});
      draw_point_stars(std::span<const InstantStars>(instants), cf.image.sky, with_stars, star_threads_, &cpu);
    }
    out.cost.star_seconds = cpu;
    out.star_wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  // The same header in every mode (threads, ranks), so files are identical.
  // The frame rate lets `lightcone encode` play the frames at the shot's
  // pace, the layout (only where not a flat mono picture) tell a player
  // they are a 360-degree video's.
  ImageMetadata& metadata = out.metadata;
  metadata = {{"lightcone/shot", shot_name_},
                                  {"lightcone/frame", std::to_string(cf.frame)},
                                  {"lightcone/fps", fmt::format("{}", fps_)},
                                  {"lightcone/spacetime", facts.spacetime},
                                  {"lightcone/supersample", std::to_string(rs_.supersample)},
                                  {"lightcone/version", LIGHTCONE_VERSION}};
  for (auto& attribute : layout_metadata(camera.video_layout())) metadata.push_back(std::move(attribute));
  if (!facts.shutter.empty()) metadata.emplace_back("lightcone/shutter", facts.shutter);
  if (const ImageWindow& w = rs_.window; w.windowed())
    metadata.emplace_back("lightcone/region", fmt::format("{},{},{},{} of {}x{}", w.x0, w.y0, w.x0 + cf.image.width,
                                                          w.y0 + cf.image.height, w.frame_width, w.frame_height));
  // Light outside the sRGB gamut (a colour shift can make it) is kept as
  // negative components, and the header says so.
  if (std::any_of(out.image(cf).rgb.begin(), out.image(cf).rgb.end(), [](float v) { return v < 0.0f; }))
    metadata.emplace_back("lightcone/colour",
                          "scene-linear, Rec. 709 primaries, D65; components below 0 are colours outside that gamut");
  return out;
}

}  // namespace lc::farm
