#include "observer/tetrad.hpp"

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

Vec3 relative_velocity(const Mat4& g, const Tetrad& f, const Vec4& u) {
  const double gamma = -contract(g, u, f.e[0]);
  return {contract(g, u, f.e[1]) / gamma, contract(g, u, f.e[2]) / gamma, contract(g, u, f.e[3]) / gamma};
}

}  // namespace lc
