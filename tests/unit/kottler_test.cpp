// Schwarzschild–de Sitter (Kottler) against figures known independently:
// its horizons, the static metric pulled back from the Kerr–Schild trace
// chart, the photon sphere at 3M whatever Λ, the shadow seen by a static
// observer (Perlick, Tsupko & Bisnovatyi-Kogan 2018), the sky's frequency
// ratio between static observers, Λ -> 0 as Schwarzschild, and the bad
// input refused.  The generic self-test (spacetime_test.cpp) checks the
// metric against its numerical derivatives at Kottler::examples().

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "camera/pinhole.hpp"
#include "core/constants.hpp"
#include "core/hit_kind.hpp"
#include "geodesic/geodesic_solver.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "shadow_check.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/kottler.hpp"

namespace lc {
namespace {

double F(double M, double lambda, double r) { return 1 - 2 * M / r - lambda * r * r / 3; }

// A root of F between lo and hi (F changes sign there), by bisection to
// rounding: independent of the class's trigonometric roots.
double root_of_F(double M, double lambda, double lo, double hi) {
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((F(M, lambda, lo) < 0) == (F(M, lambda, mid) < 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

SceneSpec kottler_scene(double M, double lambda, double r_o, double fov) {
  SceneSpec fs;
  fs.spacetime = Kottler(M, lambda);
  fs.observer = StaticObserver::Params{{0, r_o, 90 * degree, 0}};
  fs.camera.get<PinholeParams>().fov = fov;
  return fs;
}

TEST(Kottler, HorizonsAreTheRootsOfF) {
  for (const auto& [M, lambda] : {std::pair{1.0, 0.01}, {1.0, 1e-4}, {1.0, 0.1}, {2.0, 0.02}, {1.0, 1e-10}}) {
    const Kottler k(M, lambda);
    // F < 0 just outside 0 and beyond sqrt(3/Λ); F > 0 at the static radius.
    const double rs = std::cbrt(3 * M / lambda);
    EXPECT_NEAR(k.horizon_radius(), root_of_F(M, lambda, 1e-9, rs), 1e-12 * k.horizon_radius()) << lambda;
    EXPECT_NEAR(k.cosmological_horizon_radius(), root_of_F(M, lambda, rs, std::sqrt(3 / lambda)),
                1e-12 * k.cosmological_horizon_radius())
        << lambda;
    EXPECT_NEAR(k.static_radius(), rs, 1e-12 * rs);
    EXPECT_GT(k.horizon_radius(), 2 * M);
    EXPECT_LT(k.horizon_radius(), 3 * M);
    EXPECT_NEAR(k.sky_source_lapse(0), std::sqrt(F(M, lambda, rs)), 1e-12);
  }
  // de Sitter: no hole, the horizon at sqrt(3/Λ); a source at rest at its
  // centre, lapse 1.
  const Kottler ds(0.0, 0.03);
  EXPECT_NEAR(ds.cosmological_horizon_radius(), 10.0, 1e-12);
  EXPECT_EQ(ds.horizon_radius(), 0.0);
  EXPECT_EQ(ds.sky_source_lapse(0), 1.0);
  // The stop rule's radius: F = kottler_stop_lapse2 there.
  const Kottler k(1.0, 0.01);
  EXPECT_NEAR(F(1.0, 0.01, k.stop_radius()), kottler_stop_lapse2, 1e-12);
}

// The Kerr–Schild metric in the static chart's basis (polar_basis, its
// columns) is the static metric -F dt^2 + dr^2/F + r^2 dΩ^2, in both
// charts, between the horizons: to 1e-9 relative (T'(r) = h/F enters
// g_tr's cancellation).
TEST(Kottler, KerrSchildIsTheStaticMetric) {
  for (const double sense : {1.0, -1.0}) {
    const Kottler k(1.0, 0.01, sense);
    for (const double r : {2.5, 3.0, 8.0, 15.0})
      for (const double th : {0.3, 1.2, 2.0}) {
        const Vec4 s = {1.0, r, th, 0.7};
        const auto b = k.polar_basis(s);
        const Mat4 g = k.metric(k.trace_from_scene(s));
        const Mat4 want = k.static_metric(s);
        const double sn = std::sin(th);
        for (int m = 0; m < 4; ++m)
          for (int n = 0; n < 4; ++n) {
            // b[3] is ∂_φ / sin θ.
            const double scale = (m == 3 ? sn : 1.0) * (n == 3 ? sn : 1.0);
            const double got = contract(g, b[m], b[n]) * scale;
            EXPECT_NEAR(got, want[m][n], 1e-9 * (1 + std::abs(want[m][n]))) << r << " " << th << " " << m << n;
          }
      }
  }
}

// Λ drops out of the orbit equation of light, so the photon sphere is at
// r = 3M for any Λ: a null ray launched along it in the equator stays on it
// for a whole turn (2π r / √F(r) of coordinate time), to 1e-8 (the orbit
// is unstable: rounding grows ~e^(2π) a turn).
TEST(Kottler, ThePhotonSphereIsAtThreeMWhateverLambda) {
  for (const double lambda : {1e-4, 0.01, 0.1}) {
    const Kottler k = Kottler(1.0, lambda).for_tracing(TimeDirection::future);
    const double r = 3.0, f = F(1.0, lambda, r);
    const Vec4 s = {0, r, 0.5 * pi, 0};
    const auto b = k.polar_basis(s);
    // u^t = 1, u^φ = √F / r: null.
    const Vec4 u = b[0] + (std::sqrt(f) / r) * b[3];
    GeodesicProblem pb;
    pb.spacetime = k;
    pb.kind = CurveKind::null;
    pb.x0 = k.trace_from_scene(s);
    pb.u0 = u;
    pb.stop_parameter = StopParameter::coordinate_time;
    pb.stop_value = 2 * pi * r / std::sqrt(f);
    pb.samples = 9;
    pb.tolerance = 1e-13;
    const GeodesicPath path = solve_geodesic(pb);
    ASSERT_EQ(path.reason, StopReason::reached) << lambda;
    for (const GeodesicSample& p : path.samples) {
      const Vec4 sc = k.scene_from_trace(p.x);
      EXPECT_NEAR(sc[1], 3.0, 1e-8) << "Λ " << lambda;
      EXPECT_NEAR(sc[2], 0.5 * pi, 1e-8) << "Λ " << lambda;
    }
    EXPECT_NEAR(std::remainder(k.scene_from_trace(path.samples.back().x)[3], 2 * pi), 0.0, 1e-7) << lambda;
  }
}

// A static observer at r_o sees the shadow as a disc of angular radius
// sin^2 α = 27 M^2 F(r_o) / (r_o^2 (1 - 9 Λ M^2)) (Perlick, Tsupko &
// Bisnovatyi-Kogan, Phys. Rev. D 97, 104062 (2018), eq. 22; Synge's formula
// with F).  The renderer's edge to ~1e-6 rad, as Reissner–Nordström's
// (kerr_newman_test.cpp); the bound leaves a factor ~4.
TEST(Kottler, ShadowOfAStaticObserver) {
  for (const auto& [lambda, r_o, fov] : {std::tuple{0.01, 5.0, 150.0}, {0.01, 10.0, 90.0}, {1e-4, 30.0, 40.0}, {0.1, 3.5, 170.0}}) {
    const double expected = std::asin(std::sqrt(27 * F(1.0, lambda, r_o) / (r_o * r_o * (1 - 9 * lambda))));
    ShotResources res;
    const auto [left, right] =
        test::shadow_edges(build_scene(kottler_scene(1.0, lambda, r_o, fov), 200, 1, res), 200, fov);
    EXPECT_NEAR(-left, expected, 4e-6) << "Λ " << lambda << " r_o " << r_o;
    EXPECT_NEAR(right, expected, 4e-6) << "Λ " << lambda << " r_o " << r_o;
  }
}

// Every escaping ray ends at the cosmological horizon (end 0) and sees the
// sky painted there; its light comes from a source at rest at the static
// radius, so between two static observers g = √(F(r_s) / F(r_o)) whatever
// the direction (the spacetime is static: p_t is conserved).  Looking
// straight out, the sky's point is the direction looked in.
TEST(Kottler, TheSkyIsAtTheCosmologicalHorizon) {
  for (const auto& [M, lambda, r_o] : {std::tuple{1.0, 0.01, 6.0}, {0.0, 0.03, 4.0}}) {
    const Kottler k(M, lambda);
    ShotResources res;
    SceneSpec fs = kottler_scene(M, lambda, r_o, 170.0);
    const Scene scene = build_scene(fs, 9, 1, res);
    const double source = M > 0 ? F(M, lambda, k.static_radius()) : 1.0;  // de Sitter: at its centre
    const double want_g = std::sqrt(source / F(M, lambda, r_o));
    for (const double px : {0.5, 2.0, 7.0, 8.5}) {
      const RaySample s = trace_image_point(scene, px, 0.5);
      if (s.hit.kind != HitKind::sky) continue;
      EXPECT_EQ(s.hit.spacetime_end, 0);
      EXPECT_NEAR(s.hit.r, k.stop_radius(), 0.05 * k.stop_radius()) << px;
      EXPECT_NEAR(s.hit.g, want_g, 1e-6 * want_g) << "M " << M << " pixel " << px;
    }
  }
  // Straight out (+x: the camera turned round): the sky at θ = 90°, φ = 0.
  SceneSpec fs = kottler_scene(1.0, 0.01, 6.0, 10.0);
  fs.camera.get<PinholeParams>().yaw = 180;
  ShotResources res;
  const RaySample out = trace_image_point(build_scene(fs, 1, 1, res), 0.5, 0.5);
  ASSERT_EQ(out.hit.kind, HitKind::sky);
  EXPECT_NEAR(out.hit.sky_theta, 0.5 * pi, 1e-9);
  EXPECT_NEAR(std::remainder(out.hit.sky_phi, 2 * pi), 0.0, 1e-9);
}

// Λ -> 0 is Schwarzschild: at Λ = 1e-10 (r_c = 1.7e5 M) the shadow from
// 30 M is Synge's to 4e-6 rad, and the sky's points are Schwarzschild's
// directions at infinity but for a ray's offset over r_c (b / r_c < 1e-4
// here) and the escape approximations (~1e-6).
TEST(Kottler, VanishingLambdaIsSchwarzschild) {
  const double fov = 40.0;
  ShotResources res;
  const auto [left, right] = test::shadow_edges(build_scene(kottler_scene(1.0, 1e-10, 30.0, fov), 200, 1, res), 200, fov);
  EXPECT_NEAR(right, test::schwarzschild_shadow_angle_at_30(), 4e-6);
  EXPECT_NEAR(-left, test::schwarzschild_shadow_angle_at_30(), 4e-6);
  SceneSpec kerr = kottler_scene(1.0, 1e-10, 30.0, fov);
  kerr.spacetime = Kerr(1.0, 0.0);
  const Scene a = build_scene(kottler_scene(1.0, 1e-10, 30.0, fov), 16, 9, res), b = build_scene(kerr, 16, 9, res);
  int compared = 0;
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 16; ++i) {
      const RaySample p = trace_image_point(a, i + 0.5, j + 0.5), q = trace_image_point(b, i + 0.5, j + 0.5);
      ASSERT_EQ(p.hit.kind, q.hit.kind) << i << "," << j;
      if (p.hit.kind != HitKind::sky) continue;
      const auto unit = [](const HitRecord& h) {
        return Vec3{std::sin(h.sky_theta) * std::cos(h.sky_phi), std::sin(h.sky_theta) * std::sin(h.sky_phi),
                    std::cos(h.sky_theta)};
      };
      const Vec3 u = unit(p.hit), v = unit(q.hit);
      EXPECT_LT(norm3({u[0] - v[0], u[1] - v[1], u[2] - v[2]}), 1e-4) << i << "," << j;
      ++compared;
    }
  EXPECT_GT(compared, 80);  // of 144: the rest are the shadow
}

std::string refusal(double M, double lambda) {
  try {
    Kottler k(M, lambda);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

TEST(Kottler, BadInputIsRefusedWithTheReason) {
  EXPECT_NE(refusal(1.0, 0.0).find("lambda must be > 0, got 0 (lambda = 0 is Schwarzschild: lc.kerr{mass = 1})"),
            std::string::npos)
      << refusal(1.0, 0.0);
  EXPECT_NE(refusal(1.0, -0.1).find("lambda must be > 0"), std::string::npos);
  EXPECT_NE(refusal(1.0, 0.2).find("9 lambda M^2 must be < 1, got 1.8"), std::string::npos) << refusal(1.0, 0.2);
  EXPECT_NE(refusal(1.0, 0.2).find("no static region between the horizons"), std::string::npos);
  EXPECT_NE(refusal(-1.0, 0.01).find("mass must be >= 0"), std::string::npos);
  EXPECT_NE(refusal(std::nan(""), 0.01).find("finite"), std::string::npos);
  const Kottler k(1.0, 0.01);
  EXPECT_EQ(k.why_no_observer(k.trace_from_scene({0, 8.0, 1.0, 0.0})), "");
  EXPECT_EQ(k.why_no_observer({0, 20.0, 0.0, 0.0}),
            "on or beyond the cosmological horizon, where nothing can stay at rest");
  EXPECT_EQ(k.why_no_observer({0, 1.0, 0.0, 0.0}), "inside the hole's horizon");
}

}  // namespace
}  // namespace lc
