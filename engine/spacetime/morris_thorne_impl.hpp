#pragma once
// The out-of-line members of MorrisThorne<S> (spacetime/morris_thorne.hpp):
// included by each S's .cpp, which instantiates them once
// (template struct MorrisThorne<S>;).

#include <cmath>

#include "spacetime/morris_thorne.hpp"

namespace lc {

// g_ij = B δ_ij + C n_i n_j with B = r^2/R^2 (across) and C = Ω^2 - B
// (Ω^2 along n).
template <class S>
Mat4 MorrisThorne<S>::metric(const Vec4& x) const {
  const double R = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  double r, dr;
  self().template shape<double>(R - c() / R, r, dr);
  const double om = 1.0 + c() / (R * R), B = r * r / (R * R), C = om * om - B;
  Mat4 g{};
  g[0][0] = -1.0;
  for (int i = 1; i < 4; ++i)
    for (int j = 1; j < 4; ++j) g[i][j] = (i == j ? B : 0.0) + C * x[i] * x[j] / (R * R);
  return g;
}

template <class S>
Mat4 MorrisThorne<S>::inverse_metric(const Vec4& x) const {
  const double R = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  double r, dr;
  self().template shape<double>(R - c() / R, r, dr);
  const double om = 1.0 + c() / (R * R), u = R * R / (r * r), w = 1.0 / (om * om) - u;
  Mat4 g{};
  g[0][0] = -1.0;
  for (int i = 1; i < 4; ++i)
    for (int j = 1; j < 4; ++j) g[i][j] = (i == j ? u : 0.0) + w * x[i] * x[j] / (R * R);
  return g;
}

// ∂_k g_ij = B' n_k δ_ij + C' n_k n_i n_j + C (∂_k n_i n_j + n_i ∂_k n_j),
// ∂_k n_i = (δ_ik - n_i n_k)/R, ' = d/dR.
template <class S>
Mat4Derivs MorrisThorne<S>::metric_derivatives(const Vec4& x) const {
  const double R = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  double r, dr;
  self().template shape<double>(R - c() / R, r, dr);
  const double om = 1.0 + c() / (R * R), d_om = -2.0 * c() / (R * R * R);
  const double B = r * r / (R * R), C = om * om - B;
  const double dB = 2.0 * r * dr * om / (R * R) - 2.0 * B / R, dC = 2.0 * om * d_om - dB;
  const Vec3 n = {x[1] / R, x[2] / R, x[3] / R};
  Mat4Derivs d{};
  for (int k = 0; k < 3; ++k)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double dni = ((i == k ? 1.0 : 0.0) - n[i] * n[k]) / R, dnj = ((j == k ? 1.0 : 0.0) - n[j] * n[k]) / R;
        d[k + 1][i + 1][j + 1] = dB * n[k] * (i == j ? 1.0 : 0.0) + dC * n[k] * n[i] * n[j] + C * (dni * n[j] + n[i] * dnj);
      }
  return d;
}

template <class S>
Vec4 MorrisThorne<S>::scene_from_trace(const Vec4& x) const {
  const double R = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  // atan2, not acos(z/R): exact to rounding near the axis too.
  const double th = R > 0.0 ? std::atan2(std::hypot(x[1], x[2]), x[3]) : 0.5 * pi;
  double phi = std::atan2(x[2], x[1]);
  if (phi < 0.0) phi += two_pi;
  if (phi >= two_pi) phi = 0.0;
  return {x[0], proper_distance(R), th, phi};
}

template <class S>
Vec4 MorrisThorne<S>::scene_vector(const Vec4& x, const Vec4& v) const {
  const double R = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  const double dR = (x[1] * v[1] + x[2] * v[2] + x[3] * v[3]) / R;
  double dth, dphi;
  polar_angle_rates(x, v, R, dth, dphi);
  return {v[0], (1.0 + c() / (R * R)) * dR, dth, dphi};
}

template <class S>
std::array<Vec4, 4> MorrisThorne<S>::polar_basis(const Vec4& s) const {
  const double R = chart_radius(s[1]), th = s[2], ph = s[3];
  const double sn = std::sin(th), cs = std::cos(th), sp = std::sin(ph), cp = std::cos(ph);
  const double iom = 1.0 / (1.0 + c() / (R * R));
  return {Vec4{1.0, 0.0, 0.0, 0.0}, Vec4{0.0, iom * sn * cp, iom * sn * sp, iom * cs},
          Vec4{0.0, R * cs * cp, R * cs * sp, -R * sn}, Vec4{0.0, -R * sp, R * cp, 0.0}};
}

}  // namespace lc
