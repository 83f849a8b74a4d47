#pragma once
// Where camera rays start: an event on the observer's path (or an eye
// displaced from it, for stereo) and the orthonormal frame there.  A camera
// sample (camera/camera_sample.hpp) names an eye and a direction on its
// legs; the ray's start is then (eye.event, backward momentum from
// eye.metric and eye.frame).  The frame's own eye is the observer at the
// frame's time (SceneIn::eye); samples with their own time or a displaced
// eye get theirs from the observer's path.

#include "core/tensor.hpp"
#include "eye/tetrad.hpp"

namespace lc {

struct Eye {
  Vec4 event{};        // trace coordinates
  Vec4 scene_event{};  // scene coordinates, exact where the shot gave them (on the spin axis)
  double time = 0.0;   // scene time of the event (Boyer–Lindquist t for Kerr)
  Mat4 metric{};       // at the event, trace chart
  Tetrad frame{};      // e_0: the eye's 4-velocity; e_1..e_3: the camera's legs
  // The ZAMO's 4-velocity at the event (trace coordinates), filled only
  // where the light model splits g into its parts (light/light.hpp).
  Vec4 reference{};
};

}  // namespace lc
