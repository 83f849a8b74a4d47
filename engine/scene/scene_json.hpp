#pragma once
// SceneSpec -> JSON, for `lightcone inspect` (authors check their animation
// curves without rendering).  Angles are written in degrees, as scripts use.

#include <string>

#include "core/json.hpp"
#include "scene/scene_spec.hpp"

namespace lc {

// The frame's scene as the script gave it; `evaluated`, when not empty, is a
// JSON object added as the field "evaluated" (what the engine made of it).
std::string to_json(const SceneSpec& scene, int frame, const std::string& evaluated = {});


}  // namespace lc
