#pragma once
// What the engine made of a frame's scene, as JSON for `lightcone inspect`:
// the observer's event and tetrad and the camera's axes, in scene
// coordinates (Boyer–Lindquist t, r, theta, phi for Kerr, angles in radians
// per unit as components; Cartesian t, x, y, z otherwise), and the radii
// the rays are traced to.

#include <string>

#include "render/scene.hpp"

namespace lc {

std::string evaluated_json(const Scene& scene);

}  // namespace lc
