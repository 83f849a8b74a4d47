#pragma once
// A frame's scene as the shot gives it, with its shutter: the scene at the
// frame's moment and, where the shutter is open and the scene changes
// within it, the scene at each of the shutter's instants (the shot
// evaluated at fractional frame numbers: script/shot.hpp).  Plain data;
// render/scene_builder.hpp builds it into a Scene whose samples each take
// one instant (docs/motion_blur.md).

#include <optional>
#include <string>
#include <vector>

#include "camera/camera_spec.hpp"
#include "scene/scene_spec.hpp"
#include "scene/shutter.hpp"

namespace lc {

struct FrameSpecs {
  SceneSpec frame;  // at the frame's moment: the data layers' and the shot's facts
  Shutter shutter;  // the frame's (shot, frame's own, command line)
  // Offsets of the instants from the frame's moment (frame intervals) and
  // the scene at each; both empty where the shutter is closed or every
  // instant's scene is the frame's exactly (scene_key): then the frame
  // renders as with the shutter closed, to the bit.
  std::vector<double> times;
  std::vector<SceneSpec> instants;

  bool blurred() const { return !instants.empty(); }
};

// A cut between two cameras within one shutter, for its refusal: where
// the camera's kind, stereo layout or projection (camera/camera.hpp,
// video_layout) differs from the frame's (`at_frame`) at an instant
// (`at_instant`), both said as "lc.camera (flat, side-by-side)"; nullopt
// where they agree.  A frame blends its instants' samples pixel by pixel,
// so such a frame would mix a mono picture with a stereo pair, or a flat
// one with a sphere, under a header that describes only one of them.
struct CameraCut {
  std::string at_frame, at_instant;
};
std::optional<CameraCut> camera_cut(const CameraSpec& at_frame, const CameraSpec& at_instant);

}  // namespace lc
