#pragma once
// Where an escaping ray ends up on the sky: the bending still to come
// between the escape radius and infinity, in closed form or by quadrature,
// so that rays can stop at a modest radius (every step beyond it is a step
// that only aims the sky lookup).

#include <algorithm>
#include <cmath>

#include "core/tensor.hpp"

namespace lc {

// Inputs: the escape point x and unit spatial direction d (moving outwards,
// the angle psi between x and d below 90 deg), and the asymptotic mass M.
// Output: the unit direction at infinity.  Assumes the far field of a mass M
// in coordinates where light obeys dt = n(r) dl with a flat dl and the
// isotropic index n = (1 + M/r)^2: exact for the Majumdar–Papapetrou
// monopole (extreme Reissner–Nordström in isotropic coordinates), whose
// multipoles beyond it bend by more: O(|m1 - m2| d / r^2) for unequal
// holes, O(M d^2 / r^3) for equal ones.
//
// Method: Bouguer's invariant b = n r sin(psi) holds along the ray
// (Born & Wolf, Principles of Optics, sec. 3.2.2), and the polar angle it
// sweeps to infinity is the integral of b du / sqrt(n^2 - b^2 u^2) over
// u = 1/r in [0, 1/r0].  With sin(chi) = b u / n (the local angle chi to
// the radial direction) it becomes the smooth integral over chi in [0, psi]
// of (1 + M u) / (1 - M u), with no endpoint singularity even for grazing
// exits; 8-point Gauss–Legendre.  M = 0 sweeps exactly psi: a straight line.
inline Vec3 isotropic_escape_direction(const Vec3& x, const Vec3& d, double M) {
  const double r0 = norm3(x);
  const Vec3 rh = {x[0] / r0, x[1] / r0, x[2] / r0};
  const double c = std::clamp(rh[0] * d[0] + rh[1] * d[1] + rh[2] * d[2], -1.0, 1.0);
  // The unit vector in the orbit plane perpendicular to rh, towards d.
  Vec3 w = {d[0] - c * rh[0], d[1] - c * rh[1], d[2] - c * rh[2]};
  const double s = norm3(w);
  if (s < 1e-15 || M == 0.0) return d;  // radial, or no mass: no bending
  for (auto& q : w) q /= s;
  const double psi = std::atan2(s, c);
  const double n0 = (1.0 + M / r0) * (1.0 + M / r0);
  const double b = n0 * r0 * s;
  // u from sin(chi) = b u / (1 + M u)^2: the root that tends to
  // sin(chi) / b for M -> 0, in the form without cancellation.
  auto u_at = [&](double chi) {
    const double wv = std::sin(chi);
    const double q = b - 2.0 * wv * M;
    return 2.0 * wv / (q + std::sqrt(std::max(q * q - 4.0 * wv * wv * M * M, 0.0)));
  };
  static constexpr double node[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                     0.9602898564975363};
  static constexpr double weight[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                       0.1012285362903763};
  double sweep = 0.0;
  for (int k = 0; k < 4; ++k)
    for (const double sign : {-1.0, 1.0}) {
      const double u = u_at(0.5 * psi * (1.0 + sign * node[k]));
      sweep += weight[k] * (1.0 + M * u) / (1.0 - M * u);
    }
  sweep *= 0.5 * psi;
  const double cs = std::cos(sweep), sn = std::sin(sweep);
  return {cs * rh[0] + sn * w[0], cs * rh[1] + sn * w[1], cs * rh[2] + sn * w[2]};
}

}  // namespace lc
