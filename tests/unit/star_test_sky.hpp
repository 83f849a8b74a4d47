#pragma once
// Skies for the star pass's tests (stars/star_pass.hpp and its stages): a
// pinhole camera looking along +z and the rays it casts, in flat space (each
// ray's sky direction is its own) or through a point lens's map; the
// rays any camera casts in flat space.

#include <cmath>
#include <cstddef>
#include <vector>

#include "core/constants.hpp"
#include "core/sky_point.hpp"
#include "core/tensor.hpp"
#include "stars/sky_quad.hpp"

namespace lc::test {

// A pinhole camera looking along +z: the direction through image point
// (x, y) in pixels (centres at i + 0.5), horizontal field fov (degrees).
struct Pinhole {
  int width, height;
  double fov;
  Vec3 at(double x, double y) const {
    const double t = std::tan(0.5 * fov * degree);
    return unit3({(2 * x / width - 1) * t, (2 * y - height) / width * t, 1});
  }
  // Each pixel's ray in flat space: through its centre, or (`adaptive`)
  // through (0.25, 0.25) and (0.75, 0.75) of it alternately along the row.
  std::vector<SkyPoint> sky(bool adaptive = false) const {
    std::vector<SkyPoint> s;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        SkyPoint p;
        p.dx = p.dy = adaptive ? (i % 2 == 0 ? 0.25f : 0.75f) : 0.5f;
        set_direction(p, at(i + p.dx, j + p.dy));
        s.push_back(p);
      }
    return s;
  }
  // The solid angle of pixel (i, j): its corners' spherical quad.
  double pixel_solid_angle(int i, int j) const {
    return SkyQuad{{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}}.area();
  }
  // Sky point p's direction set to the unit vector d.
  static void set_direction(SkyPoint& p, const Vec3& d) {
    p.theta = std::acos(d[2]);
    p.phi = std::atan2(d[1], d[0]);
    if (p.phi < 0) p.phi += two_pi;
  }
};

// The pinhole's rays at the pixel centres through a point lens on the axis
// of Einstein angle `einstein` (rad, small-angle map: source = image (1 -
// einstein^2 / t^2)): a shadow (no sky) within 0.3 einstein, two images of
// each star, a crowded ring.
inline std::vector<SkyPoint> point_lens_sky(const Pinhole& cam, double einstein) {
  std::vector<SkyPoint> sky = cam.sky();
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      SkyPoint& p = sky[static_cast<std::size_t>(j * cam.width + i)];
      const Vec3 d = cam.at(i + p.dx, j + p.dy);
      const double x = d[0] / d[2], y = d[1] / d[2], t = std::hypot(x, y);
      if (t < 0.3 * einstein) {
        p.theta = -1;  // the shadow
        continue;
      }
      const double f = 1 - einstein * einstein / (t * t);
      Pinhole::set_direction(p, unit3({x * f, y * f, 1}));
    }
  return sky;
}

// The rays of any camera (a unit direction through image point (x, y):
// `at`) in flat space, through each pixel's centre or (`adaptive`) through
// (0.25, 0.25) and (0.75, 0.75) of it alternately along the row, as
// Pinhole::sky.
template <class Directions>
std::vector<SkyPoint> flat_sky(const Directions& at, int width, int height, bool adaptive = false) {
  std::vector<SkyPoint> s;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      SkyPoint p;
      p.dx = p.dy = adaptive ? (i % 2 == 0 ? 0.25f : 0.75f) : 0.5f;
      Pinhole::set_direction(p, at(i + p.dx, j + p.dy));
      s.push_back(p);
    }
  return s;
}

}  // namespace lc::test
