// The Boyer–Lindquist–Mino integrator of Kerr null rays (kerr_mino.hpp):
// its first integrals, and cases known in closed form.

#include "geodesic/kerr_mino.hpp"
#include "geodesic/null_ray.hpp"
#include "spacetime/kerr.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace lc {
namespace {

// U(u) = Pu^2 - u^2 D K and Theta for the state's constants: (du/dl)^2 and
// w^2 must match them.
double radial_potential(const KerrMinoConstants& k, double u) {
  const double Pu = k.E + k.alpha * u * u;
  return Pu * Pu - u * u * (1 - 2 * k.M * u + k.a2 * u * u) * k.K;
}
double polar_potential(const KerrMinoConstants& k, double c, double s) {
  const double Q = k.K - (k.L - k.aE) * (k.L - k.aE);
  return Q + k.a2E2 * c * c - (k.L == 0 ? 0.0 : k.L2 * c * c / (s * s));
}

// A ray from r0 in the given BL direction constants, moving inwards.
KerrMinoStart inward_ray(double M, double a, double r0, double theta, double L, double p_theta) {
  KerrMinoStart st = kerr_mino_start(M, a, 0.0, {0, r0, theta, 0}, {-1, 0, p_theta, L});
  st.y0[5] = std::sqrt(radial_potential(st.k, 1 / r0));  // du/dl > 0: r falls
  return st;
}

TEST(KerrMino, FirstIntegralsHoldAlongRaysThatWindRoundTheHole) {
  // Rays from r = 30 near the critical impact parameters of a = 0.9: they
  // wind round the photon region, with radial and polar turning points.
  // At tolerance 1e-10 the potentials stay matched to 1e-8 of E^2 (the
  // second-order form does not enforce them; only the integrator does).
  const double M = 1, a = 0.9;
  int escaped = 0, captured = 0;
  for (double b : {-7.2, -6.9, -3.0, 0.5, 2.5, 3.0, 4.5, 6.0}) {
    for (double pth : {-3.0, 0.0, 2.0}) {
      const KerrMinoStart st = inward_ray(M, a, 30, 80 * degree, b, pth);
      double worst_u = 0, worst_th = 0;
      RayOptions o;
      o.control.rtol = o.control.atol = 1e-10;
      auto check = [&](const MinoStep& step, MinoResult&) {
        const MinoState y = step.at(step.t0 + step.h);
        worst_u = std::max(worst_u, std::abs(y[5] * y[5] - radial_potential(st.k, y[1])));
        worst_th = std::max(worst_th, std::abs(y[6] * y[6] - polar_potential(st.k, y[2], y[3])) / std::max(1.0, st.k.K));
        worst_th = std::max(worst_th, std::abs(y[2] * y[2] + y[3] * y[3] - 1.0));
        return false;
      };
      const MinoResult res = trace_kerr_mino(st, Kerr(M, a).capture_radius(), o.control, o.max_steps, check);
      ASSERT_TRUE(res.reason == StopReason::escaped || res.reason == StopReason::horizon) << "b " << b << " p_theta " << pth << " " << to_string(res.reason) << " steps " << res.steps;
      (res.reason == StopReason::escaped ? escaped : captured)++;
      EXPECT_LT(worst_u, 1e-8) << "b " << b << " p_theta " << pth;
      EXPECT_LT(worst_th, 1e-8) << "b " << b << " p_theta " << pth;
    }
  }
  EXPECT_GT(escaped, 3);
  EXPECT_GT(captured, 3);
}

TEST(KerrMino, FlatSpaceIsAHarmonicOscillationInU) {
  // M = a = 0, equatorial, impact parameter b: u = cos(b (l - l_p)) / b, the
  // straight line in Mino time (l_p: periapsis), and phi = b l.  Exact to the
  // tolerance over the whole path out to r = 1000.
  const double b = 10, r0 = 30;
  const KerrMinoStart st = inward_ray(0, 0, r0, 0.5 * pi, b, 0);
  const double lp = std::acos(b / r0) / b;
  double worst_u = 0, worst_phi = 0;
  RayOptions o;
  o.control.rtol = o.control.atol = 1e-10;
  auto check = [&](const MinoStep& step, MinoResult&) {
    for (int k = 0; k <= 4; ++k) {  // the dense output between steps too
      const double l = step.t0 + step.h * k / 4;
      worst_u = std::max(worst_u, std::abs(step.component(1, l) - std::cos(b * (l - lp)) / b));
      worst_phi = std::max(worst_phi, std::abs(step.component(4, l) - b * l));
    }
    return false;
  };
  const MinoResult res = trace_kerr_mino(st, 0.0, o.control, o.max_steps, check);
  EXPECT_EQ(res.reason, StopReason::escaped);
  // A smooth oscillation, no pole to crawl towards: ~1.5 rad of phase at
  // the step a 5th-order method allows at 1e-10 (in r it took ~350 steps).
  EXPECT_LT(res.steps, 80);
  EXPECT_LT(worst_u, 1e-9);
  EXPECT_LT(worst_phi, 1e-8);
}

TEST(KerrMino, SchwarzschildPeriapsisOfAnEquatorialRay) {
  // a = 0, equatorial, impact parameter b: the periapsis is the largest root
  // of r^3 - b^2 r + 2 M b^2 = 0 (Chandrasekhar 1983, sec. 20), found here
  // by bisection.
  const double b = 6;
  auto f = [&](double r) { return r * r * r - b * b * r + 2 * b * b; };
  double lo = 3, hi = 6;  // f(3) < 0 < f(6)
  for (int i = 0; i < 200; ++i) (f(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
  const KerrMinoStart st = inward_ray(1, 0, 50, 0.5 * pi, b, 0);
  double u_max = 0;
  RayOptions o;
  o.control.rtol = o.control.atol = 1e-12;
  auto track = [&](const MinoStep& step, MinoResult&) {
    for (int k = 0; k <= 256; ++k) u_max = std::max(u_max, step.component(1, step.t0 + step.h * k / 256));
    return false;
  };
  const MinoResult res = trace_kerr_mino(st, 2.0, o.control, o.max_steps, track);
  EXPECT_EQ(res.reason, StopReason::escaped);
  // Sampled at 1/256 of a step near a flat maximum: the miss is second order.
  EXPECT_NEAR(1 / u_max, lo, 1e-7);
}

}  // namespace
}  // namespace lc
