#include "stars/sky_quad.hpp"

#include <algorithm>
#include <cmath>

namespace lc {

namespace {

// 2D cross product.
double cross2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

}  // namespace

double spherical_triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double num = std::abs(dot3(a, cross3(b, c)));
  const double den = 1.0 + dot3(a, b) + dot3(b, c) + dot3(c, a);
  return 2.0 * std::atan2(num, den);
}

double SkyQuad::area() const {
  return spherical_triangle_area(c[0], c[1], c[2]) + spherical_triangle_area(c[0], c[2], c[3]);
}

std::optional<std::array<double, 2>> SkyQuad::locate(const Vec3& d) const {
  // The tangent plane at the centre direction n, with axes e1, e2.
  Vec3 n = {0.0, 0.0, 0.0};
  for (const Vec3& k : c)
    for (int i = 0; i < 3; ++i) n[i] += k[i];
  const double nn = std::sqrt(dot3(n, n));
  if (!(nn > 0.0)) return std::nullopt;
  for (double& x : n) x /= nn;
  if (dot3(d, n) <= 0.0) return std::nullopt;  // the far hemisphere has no projection
  Vec3 e1 = cross3(n, std::abs(n[2]) < 0.9 ? Vec3{0.0, 0.0, 1.0} : Vec3{1.0, 0.0, 0.0});
  const double l1 = std::sqrt(dot3(e1, e1));
  for (double& x : e1) x /= l1;
  const Vec3 e2 = cross3(n, e1);
  auto project = [&](const Vec3& v) {
    const double h = dot3(v, n);
    return std::array<double, 2>{dot3(v, e1) / h, dot3(v, e2) / h};
  };
  std::array<std::array<double, 2>, 4> p;
  for (int k = 0; k < 4; ++k) {
    if (dot3(c[k], n) <= 0.0) return std::nullopt;
    p[k] = project(c[k]);
  }
  const auto q = project(d);
  // Invert q = (1-u)(1-v) p0 + u(1-v) p1 + u v p2 + (1-u) v p3 for (u, v):
  // with e = p1 - p0, f = p3 - p0, g = p0 - p1 + p2 - p3, h = q - p0,
  // u = (h - v f) / (e + v g) where the quadratic in v,
  // (g x f) v^2 + (e x f + h x g) v + h x e = 0, has a root in [0, 1]
  // (Quilez's inverse bilinear interpolation).
  const double ex = p[1][0] - p[0][0], ey = p[1][1] - p[0][1];
  const double fx = p[3][0] - p[0][0], fy = p[3][1] - p[0][1];
  const double gx = p[0][0] - p[1][0] + p[2][0] - p[3][0], gy = p[0][1] - p[1][1] + p[2][1] - p[3][1];
  const double hx = q[0] - p[0][0], hy = q[1] - p[0][1];
  const double k2 = cross2(gx, gy, fx, fy);
  const double k1 = cross2(ex, ey, fx, fy) + cross2(hx, hy, gx, gy);
  const double k0 = cross2(hx, hy, ex, ey);
  auto u_of = [&](double v) {
    const double dx = ex + v * gx, dy = ey + v * gy;
    return std::abs(dx) > std::abs(dy) ? (hx - v * fx) / dx : (hy - v * fy) / dy;
  };
  // Rounding may put a corner or an edge a hair outside: locate_slack of
  // slack (a direction on a shared edge is then in both quads; callers that
  // must count it once keep u, v < 1 - locate_slack).
  auto inside = [](double x) { return x >= -locate_slack && x <= 1.0 + locate_slack; };
  auto clamped = [](double u, double v) { return std::array<double, 2>{u, v}; };
  const double scale = std::abs(k1) + std::abs(k0) + std::abs(k2);
  if (std::abs(k2) <= 1e-12 * scale) {
    // A parallelogram: the equation is linear in v.
    if (k1 == 0.0) return std::nullopt;
    const double v = -k0 / k1, u = u_of(v);
    if (inside(u) && inside(v)) return clamped(u, v);
    return std::nullopt;
  }
  const double disc = k1 * k1 - 4.0 * k0 * k2;
  if (disc < 0.0) return std::nullopt;
  const double w = std::sqrt(disc);
  for (const double v : {(-k1 - w) / (2.0 * k2), (-k1 + w) / (2.0 * k2)}) {
    const double u = u_of(v);
    if (inside(u) && inside(v)) return clamped(u, v);
  }
  return std::nullopt;
}

}  // namespace lc
