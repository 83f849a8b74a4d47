// A charged hole (Kerr–Newman: spacetime/kerr.hpp with a charge) against
// figures known independently: its circular photon orbits, its innermost
// stable circular orbit, its disk's circular geodesics, and the edge of its
// shadow — Reissner–Nordström's for a static observer at finite distance in
// closed form, Kerr–Newman's from the spherical photon orbits' critical
// curve for a distant one — on both integrators, which must also agree with
// each other pixel by pixel.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "camera/pinhole.hpp"
#include "core/constants.hpp"
#include "core/hit_kind.hpp"
#include "objects/disk.hpp"
#include "render/accuracy.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "shadow_check.hpp"
#include "spacetime/kerr.hpp"

namespace lc {
namespace {

// The minimum of f on [lo, hi] by golden-section search (f unimodal there).
template <class F>
double argmin(F&& f, double lo, double hi) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = lo, b = hi;
  for (int i = 0; i < 200 && b - a > 1e-13; ++i) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    (f(c) < f(d) ? b : a) = f(c) < f(d) ? d : c;
  }
  return 0.5 * (a + b);
}

// The critical impact parameters of a Kerr–Newman photon orbit at radius r
// (M = 1): xi = L/E and eta = Q_Carter/E^2 from R(r) = R'(r) = 0 with
// R = (r^2 + a^2 - a xi)^2 - Delta (eta + (xi - a)^2) — Delta' = 2 (r - M)
// as in Kerr, so Kerr's derivation carries over with Delta's new constant.
struct Critical {
  double xi, eta;
};
Critical critical(double a, double q, double r) {
  const double delta = r * r - 2 * r + a * a + q * q;
  const double xi = ((r * r + a * a) * (r - 1) - 2 * r * delta) / (a * (r - 1));
  return {xi, 4 * r * r * delta / ((r - 1) * (r - 1)) - (xi - a) * (xi - a)};
}

TEST(KerrNewman, ReissnerNordstromPhotonSphere) {
  // r_ph = (3M + sqrt(9M^2 - 8Q^2)) / 2; Q = M: 2M.
  for (double q : {0.3, 0.7, 0.95, 1.0}) {
    const Kerr k(1.0, 0.0, q);
    const double expected = 0.5 * (3 + std::sqrt(9 - 8 * q * q));
    EXPECT_NEAR(k.photon_orbit_radius(true), expected, 1e-12) << "Q " << q;
    EXPECT_NEAR(k.photon_orbit_radius(false), expected, 1e-12) << "Q " << q;
  }
}

TEST(KerrNewman, EquatorialPhotonOrbitsHaveNoCarterConstant) {
  // A circular equatorial photon orbit is the spherical orbit with eta = 0:
  // the engine's radii (roots of its own equation) must make eta vanish.
  for (auto [a, q] : {std::pair{0.5, 0.5}, {0.9, 0.3}, {0.2, 0.9}, {0.6, 0.75}}) {
    const Kerr k(1.0, a, q);
    const double rp = k.photon_orbit_radius(true), rr = k.photon_orbit_radius(false);
    EXPECT_LT(rp, rr);
    EXPECT_GT(rp, k.horizon_radius());
    // eta is a difference of terms ~10..100: 1e-9 of them.
    EXPECT_NEAR(critical(a, q, rp).eta, 0.0, 1e-8) << "a " << a << " Q " << q;
    EXPECT_NEAR(critical(a, q, rr).eta, 0.0, 1e-8) << "a " << a << " Q " << q;
  }
  // Extremal (a^2 + Q^2 = M^2): the prograde orbit is on the horizon, r = M,
  // as for an extremal Kerr hole.
  EXPECT_NEAR(Kerr(1.0, 0.6, 0.8).photon_orbit_radius(true), 1.0, 1e-12);
  // Uncharged: Bardeen, Press & Teukolsky's closed form (a = 0.9: 1.5578 and 3.9103).
  EXPECT_NEAR(Kerr(1.0, 0.9).photon_orbit_radius(true), 1.5578, 1e-4);
  EXPECT_NEAR(Kerr(1.0, 0.9).photon_orbit_radius(false), 3.9103, 1e-4);
}

// The energy per unit mass of a co-rotating circular equatorial geodesic of
// a Kerr–Newman hole (M = 1, a >= 0), e.g. Dadhich & Kale 1977 (J. Math.
// Phys. 18, 1727); the ISCO is its minimum.
double circular_energy(double a, double q, double r) {
  const double s = std::sqrt(r - q * q);
  return (r * r - 2 * r + q * q + a * s) / (r * std::sqrt(r * r - 3 * r + 2 * q * q + 2 * a * s));
}

TEST(KerrNewman, IscoIsTheMinimumOfTheCircularOrbitsEnergy) {
  // The engine solves dE/dr = 0 as a polynomial condition; here E itself is
  // minimised.  A minimum is flat: golden section finds its place to ~1e-7.
  for (auto [a, q] : {std::pair{0.0, 0.5}, {0.0, 0.9}, {0.5, 0.3}, {0.9, 0.2}, {0.3, 0.9}}) {
    const Kerr k(1.0, a, q);
    const double expected = argmin([&](double r) { return circular_energy(a, q, r); }, k.photon_orbit_radius(true) + 1e-3, 8.0);
    EXPECT_NEAR(k.isco_radius(), expected, 1e-6) << "a " << a << " Q " << q;
  }
  // Reissner–Nordström: 6M at Q = 0, 4M at Q = M (extremal), and the cubic
  // r^3 - 6 r^2 + 9 Q^2 r - 4 Q^4 = 0 at Q = 0.5: 5.6066.
  EXPECT_NEAR(Kerr(1.0, 0.0, 1.0).isco_radius(), 4.0, 1e-9);
  EXPECT_NEAR(Kerr(1.0, 0.0, 1e-4).isco_radius(), 6.0, 1e-6);
  EXPECT_NEAR(Kerr(1.0, 0.0, 0.5).isco_radius(), 5.6066, 1e-4);
  const double r = Kerr(1.0, 0.0, 0.5).isco_radius();
  EXPECT_NEAR(r * r * r - 6 * r * r + 9 * 0.25 * r - 4 * 0.0625, 0.0, 1e-9);
}

TEST(KerrNewman, DiskMatterOutsideTheIscoIsOnCircularGeodesics) {
  // u = u^t (1, 0, 0, Omega) is a circular equatorial geodesic where
  // d_r g_tt + 2 Omega d_r g_tphi + Omega^2 d_r g_phiphi = 0 (the r
  // component of the geodesic equation), and is normalised.  Derivatives by
  // central differences (step 1e-5: error ~1e-10).
  for (auto [a, q] : {std::pair{0.0, 0.8}, {0.6, 0.5}, {-0.7, 0.4}}) {
    const Kerr k(1.0, a, q);
    for (double r : {k.isco_radius() + 0.01, 7.0, 20.0}) {
      const Vec4 u = k.disk_velocity_bl(r);
      const double om = u[3] / u[0], h = 1e-5;
      const Mat4 gp = k.bl_metric({0, r + h, 0.5 * pi, 0}), gm = k.bl_metric({0, r - h, 0.5 * pi, 0});
      auto d = [&](int m, int n) { return (gp[m][n] - gm[m][n]) / (2 * h); };
      EXPECT_NEAR(d(0, 0) + 2 * om * d(0, 3) + om * om * d(3, 3), 0.0, 1e-8) << "a " << a << " Q " << q << " r " << r;
      const Mat4 g = k.bl_metric({0, r, 0.5 * pi, 0});
      EXPECT_NEAR(g[0][0] * u[0] * u[0] + 2 * g[0][3] * u[0] * u[3] + g[3][3] * u[3] * u[3], -1.0, 1e-12);
      EXPECT_EQ(om > 0, a >= 0) << "co-rotating";
    }
  }
}

SceneSpec charged_scene(double a, double q, double r, double theta_deg, double fov, bool disk) {
  SceneSpec fs;
  fs.spacetime = Kerr(1.0, a, q);
  fs.observer = StaticObserver::Params{{0, r, theta_deg * degree, 0}};
  fs.camera.get<PinholeParams>().fov = fov;
  if (disk) fs.objects.push_back(Disk::Params{6, 15, 9, 24});
  return fs;
}

Scene scene_on(const SceneSpec& fs, int W, int H, KerrChart chart, ShotResources& res) {
  RayOptions o;
  o.kerr_chart = chart;
  return build_scene(fs, W, H, res, o);
}

constexpr KerrChart both_charts[] = {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild};

TEST(KerrNewman, ReissnerNordstromShadowOfAStaticObserver) {
  // A static observer at r_o sees the shadow as a disc of angular radius
  // sin(alpha) = r_ph sqrt(f(r_o)) / (r_o sqrt(f(r_ph))), f = 1 - 2M/r + Q^2/r^2
  // (Synge's formula with f; e.g. Perlick & Tsupko 2022, Phys. Rep. 947, 1,
  // eq. 27).  Both integrators decide the edge to ~1e-6 rad (the renderer's
  // Schwarzschild test); the bound leaves a factor ~4.
  const double ro = 30.0, fov = 30.0;
  for (double q : {0.5, 0.9, 1.0}) {
    const double rph = 0.5 * (3 + std::sqrt(9 - 8 * q * q));
    auto f = [&](double r) { return 1 - 2 / r + q * q / (r * r); };
    const double expected = std::asin(rph * std::sqrt(f(ro)) / (ro * std::sqrt(f(rph))));
    for (auto chart : both_charts) {
      ShotResources res;
      const auto [left, right] = test::shadow_edges(scene_on(charged_scene(0.0, q, ro, 90, fov, false), 200, 1, chart, res), 200, fov);
      EXPECT_NEAR(-left, expected, 4e-6) << "Q " << q;
      EXPECT_NEAR(right, expected, 4e-6) << "Q " << q;
    }
  }
}

TEST(KerrNewman, ShadowEdgesOfADistantObserverAreTheCriticalCurves) {
  // For an observer far out at inclination theta_o the shadow's edge is the
  // critical curve alpha = -xi / sin(theta_o), beta^2 = eta + a^2 cos^2 - xi^2
  // cot^2 (Bardeen 1973; Kerr–Newman e.g. de Vries 2000, CQG 17, 123): along
  // the centre row beta = 0, at two radii r of spherical photon orbits found
  // here by bisection.  A static observer at r_o = 2000 M sees the impact
  // parameter b at sin(angle) = b sqrt(f(r_o)) / r_o to O(M/r_o) of b's
  // offset: the bound, 3e-3 M on b ~ 2..7 M, covers that and the edge's
  // bisection.  Which edge is which side depends on the sense of the
  // spin, checked elsewhere: here the two edges' sizes.
  const double ro = 2000.0, fov = 0.6;
  for (auto [a, q, th] : {std::tuple{0.6, 0.5, 90.0}, {0.9, 0.3, 90.0}, {0.5, 0.7, 60.0}, {0.3, 0.9, 30.0}}) {
    const Kerr k(1.0, a, q);
    const double ct = std::cos(th * degree), st = std::sin(th * degree);
    auto beta2 = [&](double r) {
      const Critical c = critical(a, q, r);
      return c.eta + a * a * ct * ct - c.xi * c.xi * ct * ct / (st * st);
    };
    // beta^2 > 0 between the two roots inside the photon region.
    const double r_lo = k.photon_orbit_radius(true), r_hi = k.photon_orbit_radius(false);
    const double r_mid = argmin([&](double r) { return -beta2(r); }, r_lo, r_hi);
    auto root = [&](double lo, double hi) {  // beta2(lo) and beta2(hi) of opposite signs
      // In the equatorial plane (cos = 0) the roots are the interval's ends,
      // the equatorial photon orbits, where beta2 = eta is 0 to rounding.
      if (std::abs(beta2(lo)) < 1e-9) return lo;
      if (std::abs(beta2(hi)) < 1e-9) return hi;
      const bool lo_neg = beta2(lo) < 0;
      for (int i = 0; i < 100; ++i) {
        const double m = 0.5 * (lo + hi);
        ((beta2(m) < 0) == lo_neg ? lo : hi) = m;
      }
      return 0.5 * (lo + hi);
    };
    std::vector<double> expected = {std::abs(critical(a, q, root(r_lo, r_mid)).xi / st),
                                    std::abs(critical(a, q, root(r_mid, r_hi)).xi / st)};
    std::sort(expected.begin(), expected.end());
    const double scale = ro / std::sqrt(1 - 2 / ro + q * q / (ro * ro));
    for (auto chart : both_charts) {
      ShotResources res;
      const auto [left, right] = test::shadow_edges(scene_on(charged_scene(a, q, ro, th, fov, false), 400, 1, chart, res), 400, fov);
      std::vector<double> seen = {std::sin(-left) * scale, std::sin(right) * scale};
      std::sort(seen.begin(), seen.end());
      EXPECT_NEAR(seen[0], expected[0], 3e-3) << "a " << a << " Q " << q << " theta " << th;
      EXPECT_NEAR(seen[1], expected[1], 3e-3) << "a " << a << " Q " << q << " theta " << th;
    }
  }
}

TEST(KerrNewman, FastPathAgreesWithKerrSchild) {
  // The charge enters the two formulations differently (Delta's constant in
  // Mino time; f's numerator in Kerr–Schild): the disk as both see it, with
  // the renderer's Kerr test's bounds (renderer_test.cpp), on a charged
  // spinning hole seen from 30 M at 80 degrees.
  const SceneSpec fs = charged_scene(0.6, 0.6, 30, 80, 40, true);
  auto samples = [&](KerrChart chart, double tol) {
    ShotResources res;
    RayOptions o;
    o.kerr_chart = chart;
    o.control.rtol = o.control.atol = tol;
    o.control.h_min = 1e-14;
    const Scene scene = build_scene(fs, 32, 32, res, o);
    std::vector<RaySample> out;
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i) out.push_back(trace_image_point(scene, i + 0.5, j + 0.5));
    return out;
  };
  const auto ks = samples(KerrChart::kerr_schild, 1e-14);
  const auto bl = samples(KerrChart::boyer_lindquist_mino, 1e-12);
  const AccuracyReport r = compare_samples(ks, bl, fs);
  EXPECT_EQ(r.kind_mismatches, 0);
  EXPECT_EQ(r.cell_mismatches, 0);
  EXPECT_GT(r.disk_pixels, 80);
  EXPECT_LT(r.dr_max, 5e-7);
  EXPECT_LT(r.dphi_max, 5e-7);
  for (std::size_t k = 0; k < ks.size(); ++k) {
    EXPECT_EQ(ks[k].hit.order, bl[k].hit.order) << "pixel " << k;
    if (ks[k].hit.kind == Disk::hit_kind) EXPECT_NEAR(ks[k].hit.g, bl[k].hit.g, 1e-6) << "pixel " << k;
  }
}

}  // namespace
}  // namespace lc
