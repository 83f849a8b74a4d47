#pragma once
// Completed frames into the frame store: a full frame, once finished
// (stages/finish_frame.hpp), as EXR + PNG with its journal line, a preview
// as DIR/preview/<shot>.<NNNN>.png.

#include "schedule/farm_run.hpp"
#include <mutex>

#include "telemetry/event_log.hpp"
#include "store/frame_store.hpp"
#include "job/shot_survey.hpp"
#include "stages/finish_frame.hpp"

namespace lc::farm {

class StoreSink final : public FrameSink {
 public:
  // `survey` gives each frame's input hash, spacetime, sky and camera;
  // `preview_rows` the rows a preview frame has (sorted); `asset_dirs` the
  // shot's (Shot::asset_dirs), where a point-star sky's background is read;
  // `star_threads` how many threads a frame's point stars are drawn on
  // (the writer's among them; the frame is the same for any number).
  // `settings` are the journal's (frame_settings(rs) and the PNG's depth);
  // each frame stored is written to `events` too (may be null).
  StoreSink(FrameStore& store, const ShotSurvey& survey, const ShotInfo& shot, const RenderSettings& rs,
            const FrameSettings& settings, std::vector<int> preview_rows, std::vector<std::filesystem::path> asset_dirs,
            int star_threads = 1, EventLog* events = nullptr);
  void store(const CompletedFrame& frame) override;
  // CPU time spent drawing point stars so far, summed over every thread
  // that drew them (core-seconds).
  double star_seconds() const;
  // The wall time the writers spent in the stage, summed over them.
  double star_wall_seconds() const;

 private:
  // The shot's look at the frame's own exposure, where it gives one.
  Look frame_look(const FrameFacts& facts) const;

  FrameStore& store_;
  const ShotSurvey& survey_;
  Look look_;  // the shot's, for the PNGs (a frame's own exposure replaces its exposure)
  FrameSettings settings_;
  std::vector<int> preview_rows_;
  FrameFinisher finisher_;  // the stage after the pixels
  EventLog* events_;
  mutable std::mutex star_mutex_;
  double star_seconds_ = 0.0, star_wall_seconds_ = 0.0;
};

}  // namespace lc::farm
