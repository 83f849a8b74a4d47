// The Novikov–Thorne flux in closed form (Page & Thorne 1974, eq. 15n)
// against the integral it solves, evaluated numerically (their eq. 11b):
//   F(r) = -Mdot / (4 pi sqrt(-g)) * Omega_,r / (E - Omega L)^2
//          * Integral_{r_isco}^{r} (E - Omega L) L_,r dr,    sqrt(-g) = r,
// with E, L, Omega of circular orbits from Bardeen, Press & Teukolsky (1972)
// written out here again; its Newtonian limit far out; its scaling.

#include <gtest/gtest.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"
#include "light/novikov_thorne.hpp"

namespace lc {
namespace {

struct Orbit {
  double E, L, Omega;
};
// Prograde circular orbit at r around (M = 1, a >= 0).
Orbit orbit(double a, double r) {
  const double sr = std::sqrt(r), den = std::pow(r, 0.75) * std::sqrt(r * sr - 3 * sr + 2 * a);
  return {(r * sr - 2 * sr + a) / den, (r * r - 2 * a * sr + a * a) / den, 1 / (r * sr + a)};
}
// d/dr by a fourth-order central difference (h = 1e-3: error ~h^4 f^(5) ~ 1e-13).
template <class F>
double derivative(F f, double r) {
  const double h = 1e-3;
  return (f(r - 2 * h) - 8 * f(r - h) + 8 * f(r + h) - f(r + 2 * h)) / (12 * h);
}

double flux_from_definition(double a, double r_isco, double r) {
  gsl_function f;
  f.function = [](double x, void* p) {
    const double spin = *static_cast<double*>(p);
    const Orbit o = orbit(spin, x);
    return (o.E - o.Omega * o.L) * derivative([&](double y) { return orbit(spin, y).L; }, x);
  };
  f.params = &a;
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  double integral = 0, err = 0;
  gsl_integration_qags(&f, r_isco, r, 0, 1e-11, 1000, w, &integral, &err);
  gsl_integration_workspace_free(w);
  const Orbit o = orbit(a, r);
  const double dOmega = derivative([&](double x) { return orbit(a, x).Omega; }, r);
  return -1 / (4 * pi * r) * dOmega / ((o.E - o.Omega * o.L) * (o.E - o.Omega * o.L)) * integral;
}

TEST(NovikovThorne, ClosedFormSolvesPageAndThornesIntegral) {
  // Tolerance 1e-6 relative: the quadrature is good to ~1e-10 and the
  // differences to ~1e-12; the closed form is exact.
  for (const double a : {0.0, 0.5, 0.9, -0.9, 0.998}) {
    const NovikovThorneFlux F(1, a);
    const double ri = F.isco_radius();
    for (const double k : {1.01, 1.3, 2.0, 4.0, 10.0, 50.0}) {
      const double r = k * ri, expected = flux_from_definition(std::abs(a), ri, r);
      EXPECT_NEAR(F(r), expected, 1e-6 * expected) << "a " << a << " r " << r;
    }
    EXPECT_EQ(F(ri), 0.0);
    EXPECT_EQ(F(0.5 * ri), 0.0);
  }
}

TEST(NovikovThorne, FarOutItIsTheNewtonianDisk) {
  // 3 M Mdot / (8 pi r^3) to leading order; the corrections fall off as
  // sqrt(r_isco / r) times logarithms of r / M: ~7e-5 at r = 1e12 M.
  const NovikovThorneFlux F(1, 0.5);
  const double r = 1e12;
  const double newtonian = 3 / (8 * pi * r * r * r);
  EXPECT_NEAR(F(r), newtonian, 1e-4 * newtonian);
}

TEST(NovikovThorne, PeakAndScaling) {
  // Schwarzschild: the ISCO at 6 M and the flux's peak near 9.55 M (the
  // Newtonian profile with the same inner edge peaks at 49/36 * 6 = 8.17 M);
  // a hole of mass 2 is the one of mass 1 scaled: F(2r; 2M) = F(r; M) / 4
  // (a flux per area goes as M Mdot / r^3).
  const NovikovThorneFlux F(1, 0), F2(2, 0);
  EXPECT_NEAR(F.isco_radius(), 6.0, 1e-12);
  EXPECT_NEAR(F.peak_radius(), 9.55, 0.01);
  EXPECT_NEAR(F2(20.0), F(10.0) / 4, 1e-15);
  EXPECT_THROW(NovikovThorneFlux(1, 1), std::invalid_argument);
  EXPECT_THROW(NovikovThorneFlux(0, 0), std::invalid_argument);
}

TEST(NovikovThorne, TemperatureInSiUnitsIsShakuraSunyaevsFarOut) {
  // Far out the disk is the Newtonian one with a zero-torque inner edge
  // (Shakura & Sunyaev 1973): sigma T^4 = 3 G M Mdot / (8 pi R^3) (1 -
  // sqrt(R_in / R)), R in metres.  Written here in SI from scratch: 10 solar
  // masses (1.98841e31 kg) accreting 1e-8 solar masses a year, at 1e8 M
  // (Schwarzschild, R_in = 6 M).  Tolerance 1e-3: the relativistic
  // corrections to the flux fall off as sqrt(M / r) times logarithms, ~1e-3
  // at 1e8 M (1.5e-2 at 1e4 M), and T goes as its fourth root.
  const double G = 6.6743e-11, c = 299792458.0, sigma = 5.670374419e-8;
  const double mass = 10 * 1.98841e30, mdot = 1e-8 * 1.98841e30 / (365.25 * 86400);
  const double metres_per_m = G * mass / (c * c);
  for (const double geometric_mass : {1.0, 3.0}) {
    const NovikovThorneFlux F(geometric_mass, 0);
    const double r = 1e8 * geometric_mass, R = 1e8 * metres_per_m;
    const double expected =
        std::pow(3 * G * mass * mdot / (8 * pi * sigma * R * R * R) * (1 - std::sqrt(6.0 / 1e8)), 0.25);
    EXPECT_NEAR(F.temperature(r, 10, 1e-8), expected, 1e-3 * expected) << "M = " << geometric_mass;
  }
  // T ∝ (Mdot / M^2)^(1/4) at the same r / M.
  const NovikovThorneFlux F(1, 0.9);
  const double r = F.peak_radius();
  EXPECT_NEAR(F.temperature(r, 40, 16e-8) / F.temperature(r, 10, 1e-8), 1.0, 1e-12);
}

}  // namespace
}  // namespace lc
