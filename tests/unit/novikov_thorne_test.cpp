// The Novikov–Thorne flux in closed form (Page & Thorne 1974, eq. 15n)
// against the integral it solves, evaluated numerically (their eq. 11b):
//   F(r) = -Mdot / (4 pi sqrt(-g)) * Omega_,r / (E - Omega L)^2
//          * Integral_{r_isco}^{r} (E - Omega L) L_,r dr,    sqrt(-g) = r,
// with E, L, Omega of circular orbits from Bardeen, Press & Teukolsky (1972)
// written out here again; its Newtonian limit far out; its scaling.  Around
// a charged hole (Kerr–Newman), the class's tabulated integral against the
// same definition with Reissner–Nordström's and Kerr–Newman's orbits written
// out here, and its Q -> 0 limit against the closed form.

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

// Prograde circular orbit at r around a Kerr–Newman hole (M = 1, a >= 0,
// charge Q), neutral matter: at a = 0 Reissner–Nordström's
// E = (r^2 - 2r + Q^2) / (r sqrt(r^2 - 3r + 2Q^2)), L = r sqrt(r - Q^2) /
// sqrt(r^2 - 3r + 2Q^2), Omega = sqrt(r - Q^2) / r^2; with spin, the
// potential's extremum solved here in Boyer–Lindquist form: Omega from
// d_r g_tt + 2 Omega d_r g_tphi + Omega^2 d_r g_phiphi = 0, E and L from
// u_t, u_phi (Bardeen 1973's route, independent of the class's closed forms).
Orbit kn_orbit(double a, double Q, double r) {
  // The equatorial metric: g_tt = -1 + f, g_tphi = -a f, g_phiphi = r^2 +
  // a^2 + a^2 f with f = (2r - Q^2) / r^2, and d/dr of each.
  const double Q2 = Q * Q, f = (2 * r - Q2) / (r * r), df = -2 / (r * r) + 2 * Q2 / (r * r * r);
  const double gtt = -1 + f, gtp = -a * f, gpp = r * r + a * a + a * a * f;
  const double dtt = df, dtp = -a * df, dpp = 2 * r + a * a * df;
  const double Omega = (-dtp + std::sqrt(dtp * dtp - dtt * dpp)) / dpp;  // the prograde root
  const double ut = 1 / std::sqrt(-(gtt + 2 * Omega * gtp + Omega * Omega * gpp));
  return {-(gtt + Omega * gtp) * ut, (gtp + Omega * gpp) * ut, Omega};
}

double kn_flux_from_definition(double a, double Q, double r_isco, double r) {
  struct P {
    double a, Q;
  } p{a, Q};
  gsl_function f;
  f.function = [](double x, void* v) {
    const P& q = *static_cast<P*>(v);
    const Orbit o = kn_orbit(q.a, q.Q, x);
    return (o.E - o.Omega * o.L) * derivative([&](double y) { return kn_orbit(q.a, q.Q, y).L; }, x);
  };
  f.params = &p;
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  double integral = 0, err = 0;
  gsl_integration_qags(&f, r_isco, r, 0, 1e-11, 1000, w, &integral, &err);
  gsl_integration_workspace_free(w);
  const Orbit o = kn_orbit(a, Q, r);
  const double dOmega = derivative([&](double x) { return kn_orbit(a, Q, x).Omega; }, r);
  return -1 / (4 * pi * r) * dOmega / ((o.E - o.Omega * o.L) * (o.E - o.Omega * o.L)) * integral;
}

TEST(NovikovThorne, AChargedHolesDiskIsPageAndThornesIntegralOverItsOrbits) {
  // The written-out orbits first: Reissner–Nordström's closed forms.
  const Orbit rn = kn_orbit(0, 0.5, 7);
  EXPECT_NEAR(rn.E, (49 - 14 + 0.25) / (7 * std::sqrt(49 - 21 + 0.5)), 1e-14);
  EXPECT_NEAR(rn.L, 7 * std::sqrt(7 - 0.25) / std::sqrt(49 - 21 + 0.5), 1e-13);
  EXPECT_NEAR(rn.Omega, std::sqrt(7 - 0.25) / 49, 1e-15);
  // Tolerance 1e-6 relative, as for Kerr: the table's quadrature is good to
  // ~1e-12, its differences to ~1e-10.
  for (const auto& [a, Q] : {std::pair{0.0, 0.5}, {0.0, 0.95}, {0.5, 0.5}, {0.9, 0.3}, {-0.6, 0.6}}) {
    const NovikovThorneFlux F(1, a, Q);
    const double ri = F.isco_radius();
    for (const double k : {1.01, 1.3, 2.0, 4.0, 10.0, 50.0, 1e3}) {
      const double r = k * ri, expected = kn_flux_from_definition(std::abs(a), Q, ri, r);
      EXPECT_NEAR(F(r), expected, 1e-6 * expected) << "a " << a << " Q " << Q << " r " << r;
      EXPECT_NEAR(F.page_thorne(r), expected, 1e-6 * expected) << "a " << a << " Q " << Q << " r " << r;
    }
    EXPECT_EQ(F(ri), 0.0);
  }
  // Reissner–Nordström's ISCO at Q = M is 4M; at Q -> 0 the flux is Kerr's
  // closed form (the table against it, to 1e-6).
  EXPECT_NEAR(NovikovThorneFlux(1, 0, 0.999999).isco_radius(), 4.0, 1e-2);
  const NovikovThorneFlux kerr(1, 0.7), nearly(1, 0.7, 1e-9);
  for (const double r : {4.0, 6.0, 12.0, 100.0, 1e4}) {
    EXPECT_NEAR(nearly(r), kerr(r), 1e-6 * kerr(r)) << r;
    EXPECT_NEAR(kerr.page_thorne(r), kerr(r), 1e-6 * kerr(r)) << r;
  }
  EXPECT_THROW(NovikovThorneFlux(1, 0.6, 0.8), std::invalid_argument);  // a^2 + Q^2 = M^2
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
