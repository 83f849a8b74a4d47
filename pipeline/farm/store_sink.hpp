#pragma once
// Completed frames into the frame store: a full frame as EXR + PNG with its
// journal line, a preview as DIR/preview/<shot>.<NNNN>.png.

#include "farm/farm_run.hpp"
#include <mutex>

#include "farm/frame_store.hpp"
#include "farm/shot_inputs.hpp"
#include "assets/shot_resources.hpp"

namespace lc::farm {

class StoreSink final : public FrameSink {
 public:
  // `survey` gives each frame's input hash, spacetime, sky and camera;
  // `preview_rows` the rows a preview frame has (sorted); `asset_dirs` the
  // shot's (Shot::asset_dirs), where a point-star sky's background is read.
  StoreSink(FrameStore& store, const ShotSurvey& survey, const ShotInfo& shot, const RenderSettings& rs,
            std::vector<int> preview_rows, std::vector<std::filesystem::path> asset_dirs);
  void store(const CompletedFrame& frame) override;
  // Seconds spent drawing point stars so far (all writer threads).
  double star_seconds() const;

 private:
  FrameStore& store_;
  const ShotSurvey& survey_;
  std::string shot_name_;
  double fps_;
  DisplayTransform display_;  // the shot's, for the PNGs
  RenderSettings rs_;
  std::vector<int> preview_rows_;
  ShotResources resources_;  // the skies' stars, for the stage after the pixels
  mutable std::mutex star_mutex_;
  double star_seconds_ = 0.0;
};

// The journal's spelling of the settings.
FrameSettings frame_settings(const RenderSettings& rs);

}  // namespace lc::farm
