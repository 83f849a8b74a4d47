#pragma once
// FrameScene -> JSON, for `lightcone inspect` (authors check their animation
// curves without rendering).  Angles are written in degrees, as scripts use.

#include <string>

#include "scene/frame_scene.hpp"

namespace lc {

std::string to_json(const FrameScene& scene, int frame);

}  // namespace lc
