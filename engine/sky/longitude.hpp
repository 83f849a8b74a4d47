#pragma once
// What every sky does with a direction first: its longitude turned by the
// sky's `rotate` (degrees), back in [0, 2 pi); and the lookup of an
// equirectangular texture there.

#include <cmath>

#include "core/color.hpp"
#include "core/constants.hpp"
#include "image/texture.hpp"

namespace lc {

inline double rotated_longitude(double phi, double rotate_degrees) {
  phi += rotate_degrees * degree;
  return phi - two_pi * std::floor(phi / two_pi);
}

// The texture's colour at colatitude theta and longitude phi (already
// rotated): longitude 0 at the left edge, the top edge at theta = 0.
inline Color equirectangular_color(const Texture& t, double theta, double phi) {
  Color c;
  t.sample(phi / two_pi, theta / pi, c.data());
  return c;
}

}  // namespace lc
