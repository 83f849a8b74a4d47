#pragma once
// The innermost stable circular orbit of a Kerr hole, for orbits co-rotating
// with it (Bardeen, Press & Teukolsky 1972, ApJ 178, 347, eq. 2.21): the
// disk's matter (spacetime/kerr) and the Novikov–Thorne disk's inner edge
// (light/novikov_thorne) both need it.  With a charge (Kerr–Newman) the
// ISCO and the circular photon orbits are roots found numerically.

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

namespace detail {

// The largest root of g in (lo, hi], g(hi) > 0 assumed: g scanned down from
// hi in steps of (hi - lo) / 4096 to its first sign change, then bisected
// to the last bit.  lo when g has no root above it.
template <class G>
double largest_root(G&& g, double lo, double hi) {
  const double h = (hi - lo) / 4096.0;
  double b = hi;
  for (double a = hi - h; a > lo; b = a, a -= h) {
    if (g(a) > 0.0) continue;
    for (int i = 0; i < 200 && b - a > 0.0; ++i) {
      const double m = 0.5 * (a + b);
      if (m <= a || m >= b) break;
      (g(m) > 0.0 ? b : a) = m;
    }
    return b;
  }
  return lo;
}

}  // namespace detail

// Boyer–Lindquist radius of the circular equatorial photon orbit of a
// Kerr–Newman hole (mass M > 0, a^2 + Q^2 <= M^2) turning with the signed
// spin a (a < 0: against the hole's turn): the largest root of
//   r^2 - 3 M r + 2 Q^2 + 2 a sqrt(M r - Q^2) = 0
// (R = R' = 0 for the radial potential at theta = pi / 2; at Q = 0 Bardeen, Press & Teukolsky's eq. 2.18, at a = 0
// r = (3 M + sqrt(9 M^2 - 8 Q^2)) / 2).  At a^2 + Q^2 = M^2 the prograde
// one touches the horizon r_+ = M (a double root, no sign change): r_+.
inline double kerr_newman_photon_orbit_radius(double M, double a, double Q) {
  const double Q2 = Q * Q;
  const double r_plus = M + std::sqrt(std::max(0.0, M * M - a * a - Q2));
  return detail::largest_root([&](double r) { return r * r - 3.0 * M * r + 2.0 * Q2 + 2.0 * a * std::sqrt(M * r - Q2); },
                              r_plus, 4.0 * M + 1e-9 * M);
}

// Boyer–Lindquist radius of the co-rotating ISCO of a Kerr–Newman hole
// (M > 0, a^2 + Q^2 <= M^2): the largest root of dE/dr = 0 for circular
// equatorial geodesics of neutral matter,
//   M r (6 M r - r^2 - 9 Q^2 + 3 a^2) + 4 Q^2 (Q^2 - a^2) - 8 |a| (M r - Q^2)^(3/2) = 0,
// which is Bardeen et al.'s at Q = 0 and, at a = 0, Reissner–Nordström's
// M r^3 - 6 M^2 r^2 + 9 M Q^2 r - 4 Q^4 = 0.  Kerr's closed form at Q = 0.
inline double kerr_newman_isco_radius(double M, double a, double Q) {
  if (Q == 0.0) return kerr_isco_radius(M, a);
  if (!(M > 0.0)) return 0.0;
  const double Q2 = Q * Q, aa = std::abs(a);
  const auto g = [&](double r) {
    const double x = M * r - Q2;
    return -(M * r * (6.0 * M * r - r * r - 9.0 * Q2 + 3.0 * aa * aa) + 4.0 * Q2 * (Q2 - aa * aa) -
             8.0 * aa * x * std::sqrt(x));
  };
  return detail::largest_root(g, kerr_newman_photon_orbit_radius(M, aa, Q), 6.0 * M + 1e-9 * M);
}

}  // namespace lc
