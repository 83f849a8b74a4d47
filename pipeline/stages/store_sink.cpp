#include "stages/store_sink.hpp"

#include <algorithm>
#include <chrono>

#include <fmt/format.h>

#include "render/point_star_stage.hpp"

namespace lc::farm {

FrameSettings frame_settings(const RenderSettings& rs) {
  // Adaptive sampling only means something with more than one sample.
  FrameSettings s{rs.width, rs.height, rs.supersample, rs.layers, rs.adaptive && rs.supersample > 1};
  s.window = rs.window;
  return s;
}

StoreSink::StoreSink(FrameStore& store, const ShotSurvey& survey, const ShotInfo& shot, const RenderSettings& rs,
                     const FrameSettings& settings, std::vector<int> preview_rows,
                     std::vector<std::filesystem::path> asset_dirs, int star_threads, EventLog* events)
    : store_(store), survey_(survey), shot_name_(shot.name), fps_(shot.fps), look_(shot.look()), rs_(rs),
      settings_(settings), preview_rows_(std::move(preview_rows)), resources_(std::move(asset_dirs)), star_threads_(std::max(1, star_threads)), events_(events) {}

Look StoreSink::frame_look(const FrameFacts& facts) const {
  Look look = look_;
  if (facts.exposure) look.exposure = *facts.exposure;
  return look;
}

void StoreSink::store(const CompletedFrame& cf) {
  if (cf.pass == Pass::preview) {
    // Previews show no point stars: their missing rows are copies, and
    // copied rays make no patches of sky.
    FrameImage preview{cf.image.width, cf.image.height, cf.image.rgb, cf.image.layers, {}, cf.image.alpha};
    store_.write_preview(cf.frame, std::move(preview), preview_rows_, frame_look(survey_.frames.at(cf.frame)));
    return;
  }
  const FrameFacts& facts = survey_.frames.at(cf.frame);
  // The stage after the pixels: a sky's point stars, drawn on a copy (the
  // frame as the rays made it is the queue's); a frame without them is
  // written as it is (the files do not hold sky points).
  const FrameImage* written = &cf.image;
  const Camera camera(facts.camera, cf.image.width, cf.image.height, rs_.window);
  FrameImage with_stars;
  FrameCost cost{.rays = cf.stats.rays, .reused = cf.stats.reused, .core_seconds = cf.stats.seconds};
  // Its cost is CPU time, as the rays' is: the stage's threads share the
  // cores with the render threads, so wall time would count their waits.
  if (const auto stars = cf.image.sky.empty() ? std::nullopt : sky_point_stars(facts.sky, resources_)) {
    const auto start = std::chrono::steady_clock::now();
    with_stars = {cf.image.width, cf.image.height, cf.image.rgb, cf.image.layers, {}, cf.image.alpha};
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
    written = &with_stars;
    cost.star_seconds = cpu;
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    std::lock_guard lock(star_mutex_);
    star_seconds_ += cpu;
    star_wall_seconds_ += took.count();
  }
  // The same header in every mode (threads, ranks), so files are identical.
  // The frame rate lets `lightcone encode` play the frames at the shot's
  // pace, the layout (only where not a flat mono picture) tell a player
  // they are a 360-degree video's.
  ImageMetadata metadata = {{"lightcone/shot", shot_name_},
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
  if (std::any_of(written->rgb.begin(), written->rgb.end(), [](float v) { return v < 0.0f; }))
    metadata.emplace_back("lightcone/colour",
                          "scene-linear, Rec. 709 primaries, D65; components below 0 are colours outside that gamut");
  store_.write_frame(cf.frame, *written, metadata, settings_, facts.inputs, facts.parts, cost, frame_look(facts),
                     cf.makers, cf.dispatched);
  if (events_) events_->frame_stored(cf.frame, cost.core_seconds + cost.star_seconds, cost.rays);
}

double StoreSink::star_seconds() const {
  std::lock_guard lock(star_mutex_);
  return star_seconds_;
}

double StoreSink::star_wall_seconds() const {
  std::lock_guard lock(star_mutex_);
  return star_wall_seconds_;
}

}  // namespace lc::farm
