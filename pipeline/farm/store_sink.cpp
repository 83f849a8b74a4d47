#include "farm/store_sink.hpp"

#include <fmt/format.h>

namespace lc::farm {

FrameSettings frame_settings(const RenderSettings& rs) {
  // Adaptive sampling only means something with more than one sample.
  return {rs.width, rs.height, rs.supersample, rs.layers, rs.adaptive && rs.supersample > 1};
}

StoreSink::StoreSink(FrameStore& store, const ShotSurvey& survey, const ShotInfo& shot, const RenderSettings& rs,
                     std::vector<int> preview_rows)
    : store_(store), survey_(survey), shot_name_(shot.name), fps_(shot.fps), display_(shot.display()), rs_(rs),
      preview_rows_(std::move(preview_rows)) {}

void StoreSink::store(const CompletedFrame& cf) {
  if (cf.pass == Pass::preview) {
    store_.write_preview(cf.frame, cf.image, preview_rows_, display_);
    return;
  }
  const FrameFacts& facts = survey_.frames.at(cf.frame);
  // The same header in every mode (threads, ranks), so files are identical.
  // The frame rate lets `lightcone encode` play the frames at the shot's pace.
  const ImageMetadata metadata = {{"lightcone/shot", shot_name_},
                                  {"lightcone/frame", std::to_string(cf.frame)},
                                  {"lightcone/fps", fmt::format("{}", fps_)},
                                  {"lightcone/spacetime", facts.spacetime},
                                  {"lightcone/supersample", std::to_string(rs_.supersample)},
                                  {"lightcone/version", LIGHTCONE_VERSION}};
  store_.write_frame(cf.frame, cf.image, metadata, frame_settings(rs_), facts.inputs, facts.parts, cf.stats.rays,
                     display_);
}

}  // namespace lc::farm
