#pragma once
// The patch of sky that a quad of four neighbouring pixel centres sees: the
// directions at infinity of their four rays span a spherical quadrilateral,
// its solid angle (for a star's magnification, Omega_pixel / Omega_sky) and
// where in it a star lies (bilinear coordinates, for spreading the star's
// light over the four pixels so that it is conserved as the star moves).

#include <array>
#include <optional>

#include "core/tensor.hpp"

namespace lc {

// The cross product a x b.
inline Vec3 cross3(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Solid angle (sr) of the spherical triangle of unit vectors a, b, c: Van
// Oosterom & Strackee (1983, IEEE Trans. Biomed. Eng. 30, 125), tan(Omega/2)
// = |a.(b x c)| / (1 + a.b + b.c + c.a).  Accurate for tiny triangles too.
double spherical_triangle_area(const Vec3& a, const Vec3& b, const Vec3& c);

// The spherical quadrilateral with corners c[0] (u = 0, v = 0), c[1] (1, 0),
// c[2] (1, 1), c[3] (0, 1), unit vectors, seen from the centre of the unit
// sphere: corners in order around it, either orientation.
inline constexpr double locate_slack = 1e-12;

struct SkyQuad {
  std::array<Vec3, 4> c;

  // Its solid angle (sr): the two triangles (0, 1, 2) and (0, 2, 3).
  double area() const;
  // The bilinear coordinates (u, v) in [0, 1]^2 (to within locate_slack)
  // of the unit direction d,
  // found in the plane tangent to the sphere at the quad's centre (the
  // gnomonic projection keeps great circles straight, so the quad's edges
  // stay straight); nullopt when d is not inside.
  std::optional<std::array<double, 2>> locate(const Vec3& d) const;
};

}  // namespace lc
