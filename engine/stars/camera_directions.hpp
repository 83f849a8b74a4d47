#pragma once
// What the star pass knows of the camera (stars/star_pass.hpp): the unit
// direction through an image point, from which come the solid angles the
// camera sees a patch of the image and a pixel under.

#include <array>
#include <functional>

#include "core/tensor.hpp"
#include "stars/sky_quad.hpp"

namespace lc {

// The camera's unit direction through image point (x, y) in pixel units
// (the observer's local frame).
using CameraDirections = std::function<Vec3(double x, double y)>;

// An image point (x, y) in pixel units from the image's top-left corner.
using ImagePoint = std::array<double, 2>;

// The camera's solid angle (sr) of the image quad with corners p[0..3], in
// order around it: the spherical quad of their directions.
inline double camera_solid_angle(const CameraDirections& camera, const std::array<ImagePoint, 4>& p) {
  return SkyQuad{{camera(p[0][0], p[0][1]), camera(p[1][0], p[1][1]), camera(p[2][0], p[2][1]), camera(p[3][0], p[3][1])}}
      .area();
}

}  // namespace lc
