#pragma once
// What every sky does with a direction first: its longitude turned by the
// sky's `rotate` (degrees), back in [0, 2 pi); and with its colour last: the
// light times 2^`brightness` (stops); and the skies that look an
// equirectangular texture up there (image_sky, star_sky).

#include <cmath>
#include <memory>
#include <utility>

#include "core/color.hpp"
#include "core/constants.hpp"
#include "image/texture.hpp"

namespace lc {

inline double rotated_longitude(double phi, double rotate_degrees) {
  phi += rotate_degrees * degree;
  return phi - two_pi * std::floor(phi / two_pi);
}

// The factor of a sky's `brightness` (stops): 2^stops.
inline float brightness_scale(double stops) { return static_cast<float>(std::exp2(stops)); }

// c times a brightness_scale; untouched at 1, so a sky at brightness 0 gives
// exactly the colour it computed.
inline Color scaled(Color c, float scale) {
  if (scale != 1.0f)
    for (float& v : c) v *= scale;
  return c;
}

// A sky that is an equirectangular texture: longitude 0 at the left edge,
// the top edge at theta = 0, turned by `rotate` degrees, its light times
// 2^brightness.
class TextureSky {
 public:
  TextureSky(double rotate, double brightness, std::shared_ptr<const Texture> texture)
      : rotate_(rotate), scale_(brightness_scale(brightness)), texture_(std::move(texture)) {}

  // Colour in the direction (theta from +z, phi = atan2(y, x)).
  Color color(double theta, double phi) const {
    Color c;
    texture_->sample(rotated_longitude(phi, rotate_) / two_pi, theta / pi, c.data());
    return scaled(c, scale_);
  }

 private:
  double rotate_;
  float scale_;
  std::shared_ptr<const Texture> texture_;
};

}  // namespace lc
