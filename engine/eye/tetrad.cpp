#include "eye/tetrad.hpp"

#include <algorithm>
#include <cmath>

namespace lc {

Tetrad orthonormalize(const Mat4& g, const std::array<Vec4, 4>& basis, const char* who) {
  Tetrad t{};
  const double n0 = contract(g, basis[0], basis[0]);
  if (!(n0 < 0.0)) throw ObserverError(fmt::format("{}: the time direction is not timelike here", who));
  t.e[0] = (1.0 / std::sqrt(-n0)) * basis[0];
  for (int a = 1; a < 4; ++a) {
    Vec4 v = basis[a];
    // Modified Gram–Schmidt: subtract projections one leg at a time.
    for (int b = 0; b < a; ++b) {
      const double eta_bb = b == 0 ? -1.0 : 1.0;
      v = v - (contract(g, v, t.e[b]) * eta_bb) * t.e[b];
    }
    const double n = contract(g, v, v);
    if (!(n > 1e-300)) throw ObserverError(fmt::format("{}: the frame degenerates here", who));
    t.e[a] = (1.0 / std::sqrt(n)) * v;
  }
  return t;
}

Tetrad boost(const Tetrad& rest, const Vec3& v) {
  const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  if (!(v2 < 1.0)) throw ObserverError(fmt::format("velocity {} is not below the speed of light", std::sqrt(v2)));
  const double gamma = 1.0 / std::sqrt(1.0 - v2);
  Tetrad t{};
  t.e[0] = gamma * rest.e[0];
  for (int i = 0; i < 3; ++i) t.e[0] = t.e[0] + (gamma * v[i]) * rest.e[i + 1];
  // Pure boost: e'_j = e_j + gamma v_j e_0 + (gamma - 1)/v^2 v_j v^k e_k.
  const double k = v2 > 0.0 ? (gamma - 1.0) / v2 : 0.0;
  for (int j = 0; j < 3; ++j) {
    Vec4 e = rest.e[j + 1] + (gamma * v[j]) * rest.e[0];
    for (int i = 0; i < 3; ++i) e = e + (k * v[j] * v[i]) * rest.e[i + 1];
    t.e[j + 1] = e;
  }
  return t;
}

RestSpaceSpan rest_space_span(const Tetrad& f) {
  const Vec4& u = f.e[0];
  double m[3][3], tilt2 = 0.0;  // m[i][j]: coordinate i of leg j, slid along u to u's time
  for (int j = 0; j < 3; ++j) {
    const Vec4& e = f.e[j + 1];
    for (int i = 0; i < 3; ++i) m[i][j] = e[i + 1] - e[0] / u[0] * u[i + 1];
    tilt2 += e[0] * e[0];
  }
  double a[3][3];  // m^T m, symmetric and positive semi-definite
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a[i][j] = m[0][i] * m[0][j] + m[1][i] * m[1][j] + m[2][i] * m[2][j];
  const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  double top;
  if (off == 0.0) {
    top = std::max({a[0][0], a[1][1], a[2][2]});
  } else {
    const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    const double p = std::sqrt(((a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) +
                                (a[2][2] - q) * (a[2][2] - q) + 2.0 * off) / 6.0);
    double b[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) b[i][j] = (a[i][j] - (i == j ? q : 0.0)) / p;
    const double det = b[0][0] * (b[1][1] * b[2][2] - b[1][2] * b[2][1]) -
                       b[0][1] * (b[1][0] * b[2][2] - b[1][2] * b[2][0]) +
                       b[0][2] * (b[1][0] * b[2][1] - b[1][1] * b[2][0]);
    top = q + 2.0 * p * std::cos(std::acos(std::clamp(0.5 * det, -1.0, 1.0)) / 3.0);
  }
  return {std::sqrt(std::max(top, 0.0)), std::sqrt(tilt2)};
}

Vec3 relative_velocity(const Mat4& g, const Tetrad& f, const Vec4& u) {
  const double gamma = -contract(g, u, f.e[0]);
  return {contract(g, u, f.e[1]) / gamma, contract(g, u, f.e[2]) / gamma, contract(g, u, f.e[3]) / gamma};
}

}  // namespace lc
