#pragma once
// The out-of-line members of ExtremeHoles<S> (spacetime/extreme_holes.hpp):
// included by each S's .cpp, which instantiates them once
// (template struct ExtremeHoles<S>;).

#include <cmath>

#include "spacetime/extreme_holes.hpp"

namespace lc {

template <class S>
Vec4 ExtremeHoles<S>::disk_velocity(const Vec4& x) const {
  const Vec4 rest = {1.0, 0.0, 0.0, 0.0};
  const double R = std::hypot(x[1], x[2]);
  if (!(R > 0.0)) return rest;
  Vec3 grad;
  const double U = potential(x, &grad);
  const double U_R = (grad[0] * x[1] + grad[1] * x[2]) / R;
  const double pull = -2.0 * U_R / (U * U * U);              // -∂_R g_tt
  const double lever = 2.0 * U * U_R * R * R + 2.0 * U * U * R;  // ∂_R g_phiphi
  if (!(pull > 0.0) || !(lever > 0.0)) return rest;
  const double omega = std::sqrt(pull / lever);
  const double norm = 1.0 / (U * U) - omega * omega * U * U * R * R;  // -(g_tt + Omega^2 g_phiphi)
  if (!(norm > 0.0)) return rest;
  const double ut = 1.0 / std::sqrt(norm);
  return {ut, -omega * x[2] * ut, omega * x[1] * ut, 0.0};
}

template <class S>
Mat4 ExtremeHoles<S>::metric(const Vec4& x) const {
  const double U = potential(x);
  Mat4 g{};
  g[0][0] = -1.0 / (U * U);
  g[1][1] = g[2][2] = g[3][3] = U * U;
  return g;
}

template <class S>
Mat4 ExtremeHoles<S>::inverse_metric(const Vec4& x) const {
  const double U = potential(x);
  Mat4 g{};
  g[0][0] = -U * U;
  g[1][1] = g[2][2] = g[3][3] = 1.0 / (U * U);
  return g;
}

template <class S>
Mat4Derivs ExtremeHoles<S>::metric_derivatives(const Vec4& x) const {
  Vec3 grad;
  const double U = potential(x, &grad);
  Mat4Derivs d{};
  for (int j = 0; j < 3; ++j) {
    d[j + 1][0][0] = 2.0 * grad[j] / (U * U * U);
    d[j + 1][1][1] = d[j + 1][2][2] = d[j + 1][3][3] = 2.0 * U * grad[j];
  }
  return d;
}

}  // namespace lc
