#pragma once
// The stage after the pixels, where a frame is whole: a sky's point stars
// drawn from the rays' sky points (render/point_star_stage.hpp), and the
// header every frame file carries.  What the store sink then writes.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "assets/shot_resources.hpp"
#include "image/image_io.hpp"
#include "job/shot_survey.hpp"
#include "render/render_settings.hpp"
#include "schedule/frame_assembly.hpp"
#include "store/journal.hpp"

namespace lc::farm {

// A completed frame made ready to write.
struct FinishedFrame {
  std::optional<FrameImage> starred;  // the frame with its point stars, when its sky has them
  ImageMetadata metadata;             // the files' header
  FrameCost cost;                     // its rays and CPU time, the stars' included
  double star_wall_seconds = 0.0;     // the wall time the stars took
  // The picture to write: the starred copy, else the frame as the rays made it.
  const FrameImage& image(const CompletedFrame& cf) const { return starred ? *starred : cf.image; }
};

class FrameFinisher {
 public:
  // Frames of shot `shot_name` at `fps`, rendered with `rs`; a point-star
  // sky's background is read under `asset_dirs` (Shot::asset_dirs); the
  // stars are drawn on `star_threads` threads (the frame is the same for
  // any number).
  FrameFinisher(std::string shot_name, double fps, const RenderSettings& rs,
                std::vector<std::filesystem::path> asset_dirs, int star_threads);
  // Finishes `cf` (a full frame, `facts` its survey's): draws its point
  // stars on a copy (the frame as the rays made it is the queue's; a frame
  // whose sky has none is written as it is, the files hold no sky points)
  // and fills its header, the same in every mode (threads, ranks) so files
  // are identical.  Thread-safe (writers call it at once).
  FinishedFrame finish(const CompletedFrame& cf, const FrameFacts& facts);

 private:
  std::string shot_name_;
  double fps_;
  RenderSettings rs_;
  ShotResources resources_;  // the skies' stars
  int star_threads_;
};

}  // namespace lc::farm
