#pragma once
// Scene coordinates for spacetimes traced in Cartesian (t, x, y, z): the scene
// coordinates are the trace coordinates, and the polar basis is the spherical
// one about the origin.  Shared by Minkowski and the dihole.

#include <cmath>

#include "core/tensor.hpp"

namespace lc {

struct CartesianScene {
  static Vec4 trace_from_scene(const Vec4& s) { return s; }
  static Vec4 scene_from_trace(const Vec4& x) { return x; }
  static Vec4 scene_vector(const Vec4&, const Vec4& v) { return v; }
  static Vec4 scene_time_gradient(const Vec4&) { return {1.0, 0.0, 0.0, 0.0}; }

  // {∂_t, ∂_r, ∂_theta, ∂_phi / sin(theta)} of spherical coordinates about the
  // origin, with r factors divided out of the angular vectors' scale only as
  // spherical coordinates have them (|∂_theta| = r).  On the z axis phi is taken
  // as atan2(y, x) = 0, so the frame there is the limit from the x-z half-plane.
  static std::array<Vec4, 4> polar_basis(const Vec4& s) {
    const double r = std::sqrt(s[1] * s[1] + s[2] * s[2] + s[3] * s[3]);
    const double th = r > 0.0 ? std::acos(std::fmax(-1.0, std::fmin(1.0, s[3] / r))) : 0.0;
    const double ph = std::atan2(s[2], s[1]);
    const double sn = std::sin(th), cs = std::cos(th), sp = std::sin(ph), cp = std::cos(ph);
    return {Vec4{1.0, 0.0, 0.0, 0.0}, Vec4{0.0, sn * cp, sn * sp, cs},
            Vec4{0.0, r * cs * cp, r * cs * sp, -r * sn}, Vec4{0.0, -r * sp, r * cp, 0.0}};
  }
};

}  // namespace lc
