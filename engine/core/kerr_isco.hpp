#pragma once
// The innermost stable circular orbit of a Kerr hole, for orbits co-rotating
// with it (Bardeen, Press & Teukolsky 1972, ApJ 178, 347, eq. 2.21): the
// disk's matter (spacetime/kerr) and the Novikov–Thorne disk's inner edge
// (light/novikov_thorne) both need it.

#include <algorithm>
#include <cmath>

namespace lc {

// Boyer–Lindquist radius of the co-rotating ISCO of a hole of mass M > 0 and
// spin a (|a| <= M; the sign does not matter); 0 where M <= 0.
inline double kerr_isco_radius(double mass, double spin) {
  if (!(mass > 0.0)) return 0.0;
  const double chi = std::min(std::abs(spin) / mass, 1.0);
  const double z1 = 1.0 + std::cbrt(1.0 - chi * chi) * (std::cbrt(1.0 + chi) + std::cbrt(1.0 - chi));
  const double z2 = std::sqrt(3.0 * chi * chi + z1 * z1);
  return mass * (3.0 + z2 - std::sqrt((3.0 - z1) * (3.0 + z1 + 2.0 * z2)));
}

}  // namespace lc
