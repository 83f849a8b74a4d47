#pragma once
// Initial covariant momentum of a ray traced backwards from an observer.

#include <cmath>

#include "eye/tetrad.hpp"

namespace lc {

// Light seen along the spatial direction n (components on the tetrad's legs
// 1..3; any length > 0) arrived with momentum ∝ e_0 - n.  Tracing it backwards
// in time follows k = -e_0 + n̂; returns p_mu = g_{mu nu} k^nu.  Getting this
// sign wrong mirrors a Kerr image (docs/architecture.md, "Conventions").
inline Vec4 backward_ray_momentum(const Mat4& g, const Tetrad& t, const Vec3& n) {
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  Vec4 k = -1.0 * t.e[0];
  for (int i = 0; i < 3; ++i) k = k + (n[i] / len) * t.e[i + 1];
  return mat_vec(g, k);
}

}  // namespace lc
