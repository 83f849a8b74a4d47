#pragma once
// A frame's scene as the shot gives it, with its shutter: the scene at the
// frame's moment and, where the shutter is open and the scene changes
// within it, the scene at each of the shutter's instants (the shot
// evaluated at fractional frame numbers: script/shot.hpp).  Plain data;
// render/scene_builder.hpp builds it into a Scene whose samples each take
// one instant (docs/motion_blur.md).

#include <vector>

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

}  // namespace lc
