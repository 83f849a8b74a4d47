#pragma once
// A camera's input and output (after pbrt-v4's CameraSample and optional
// CameraRay): a sample names an image point and a time within the frame;
// the camera answers with the ray through it, or none where it has no ray
// (outside a dome master's disc).  A ray is a direction on the eye's
// spatial legs, the eye's displacement from the observer in the
// observer's frame (stereo), and the sample's time; render/ray_start.hpp
// makes the eye and the ray's start event from them.

#include <optional>

#include "core/tensor.hpp"

namespace lc {

struct CameraSample {
  double px = 0.0, py = 0.0;  // image point in pixel units: pixel (i, j) spans [i, i+1] x [j, j+1], j = 0 at the top
  // Its offset from the frame's moment, in frame intervals (0: the frame's
  // own moment; an instant of its shutter: render/sample_times.hpp).
  double time = 0.0;
};

struct CameraRay {
  Vec3 direction{};  // unit, on the eye's spatial legs (1, 2, 3)
  // Where the eye is, on the observer's spatial legs, in units of M (0:
  // the observer's own event).
  Vec3 eye{};
  double time = 0.0;  // the sample's time, as CameraSample::time
  bool at_observer() const { return eye[0] == 0.0 && eye[1] == 0.0 && eye[2] == 0.0; }
};

}  // namespace lc
