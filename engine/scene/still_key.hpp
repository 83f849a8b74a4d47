#pragma once
// What a frame's scene is apart from its moment: every parameter, exactly
// (hex floats), except the observer's time where the observer is fixed in
// space (static or ZAMO); empty for a free-falling observer, whose frames
// never share.  In a stationary spacetime two frames with equal
// keys are the same scene translated in time: a camera ray that never comes
// near a moving object sees the same thing in both (render/sample_memo.hpp).

#include <string>

#include "scene/scene_spec.hpp"

namespace lc {

std::string still_key(const SceneSpec& scene);

// Every parameter of the scene exactly, the observer's clock included (and
// not the frame's shutter): two scenes with equal keys are the same picture
// (a shutter's instants that all equal the frame's: scene/frame_specs.hpp).
std::string scene_key(const SceneSpec& scene);

}  // namespace lc
