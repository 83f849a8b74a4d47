// The wormholes (spacetime/morris_thorne.hpp: lc.ellis_wormhole and
// lc.interstellar_wormhole) against figures known independently: their
// shapes r(l), the chart's two universes and the inversion between them,
// the throat's apparent edge for a static observer (sin α = min r / r(l)),
// Ellis's deflection against the exact integral (2K(b/h) - π), rays through
// the throat reaching the other side's sky with their direction kept, an
// object beyond the throat within the free-flight radius, and the bad input
// refused.  The generic self-test (spacetime_test.cpp) checks the metrics
// against their numerical derivatives at each class's examples().

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "core/constants.hpp"
#include "objects/objects.hpp"
#include "spacetime/ellis_wormhole.hpp"
#include "spacetime/interstellar_wormhole.hpp"
#include "spacetime/kerr.hpp"
#include "wormhole_scene.hpp"

namespace lc {
namespace {

// Ellis's r(l) and James et al.'s (their eq. 5), written out here.
double ellis_r(double b, double l) { return std::sqrt(l * l + b * b); }
double interstellar_r(double rho, double a, double W, double l) {
  if (std::abs(l) <= a) return rho;
  const double M = W / 1.42953, x = 2 * (std::abs(l) - a) / (pi * M);
  return rho + M * (x * std::atan(x) - 0.5 * std::log(1 + x * x));
}

TEST(MorrisThorne, TheShapesAreTheirPapers) {
  const EllisWormhole e({2.0});
  const InterstellarWormhole w({1.0, 0.6, 0.3});
  for (double l : {-30.0, -2.0, -0.31, -0.3, 0.0, 0.2, 0.29, 0.31, 1.0, 7.0, 100.0}) {
    double r, dr;
    e.shape(l, r, dr);
    EXPECT_NEAR(r, ellis_r(2.0, l), 1e-14 * r) << l;
    w.shape(l, r, dr);
    EXPECT_NEAR(r, interstellar_r(1.0, 0.3, 0.3, l), 1e-14 * r) << l;
    // dr/dl by central differences (step 1e-6: truncation ~1e-12 away from
    // |l| = a, where r'' jumps and the difference is still within 1e-6).
    const double fd = (interstellar_r(1.0, 0.3, 0.3, l + 1e-6) - interstellar_r(1.0, 0.3, 0.3, l - 1e-6)) / 2e-6;
    EXPECT_NEAR(dr, fd, 1e-6) << l;
  }
  // Far out the flare is flat space's: dr/dl -> 1 (as (2/π) atan x).
  double r, dr;
  w.shape(1e6, r, dr);
  EXPECT_NEAR(dr, 1.0, 1e-6);
  EXPECT_EQ(w.params().length, 0.6);
  EXPECT_NEAR(w.params().lensing_width, 0.3, 1e-15);
}

// The chart: l <-> R exactly invertible on both sides, the throat at
// R = s/2, and x -> -c x / |x|^2 an isometry of Ellis's space that swaps
// the universes.
TEST(MorrisThorne, TheChartHoldsBothUniversesAndTheInversionSwapsThem) {
  const EllisWormhole st({2.0});
  for (double l : {-1e4, -50.0, -1.0, -1e-9, 0.0, 1e-9, 1.0, 50.0, 1e4}) {
    const double R = st.chart_radius(l);
    EXPECT_GT(R, 0.0);
    EXPECT_NEAR(st.proper_distance(R), l, 1e-12 * std::max(1.0, std::abs(l))) << l;
    EXPECT_NEAR(st.chart_radius(-l), 1.0 / R, 1e-12 / R) << "R(-l) = c/R, c = 1 at b = 2";
  }
  EXPECT_DOUBLE_EQ(st.chart_radius(0.0), 1.0);
  // The spatial metric pulled back through the inversion (c = 1):
  // J = -(I - 2 n n)/R^2, g'(x') = J^T g(x) J ... equals g at x'.
  const Vec4 x = {0.0, 0.3, -0.2, 0.5};
  const double R2 = 0.3 * 0.3 + 0.2 * 0.2 + 0.5 * 0.5;
  const Vec4 xi = {0.0, -x[1] / R2, -x[2] / R2, -x[3] / R2};
  const Mat4 g = st.metric(x), gi = st.metric(xi);
  double J[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J[i][j] = -((i == j ? 1.0 : 0.0) - 2 * xi[i + 1] * xi[j + 1] * R2) * R2;
  // J: d x / d x' at x' (x = -x'/|x'|^2, |x'|^2 = 1/R2).
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double pulled = 0.0;
      for (int k = 0; k < 3; ++k)
        for (int m = 0; m < 3; ++m) pulled += J[k][i] * g[k + 1][m + 1] * J[m][j];
      EXPECT_NEAR(pulled, gi[i + 1][j + 1], 1e-12 * std::abs(gi[1][1])) << i << j;
    }
}

// Escape far enough that Ellis's remaining bending (~ b^2 h / l^3) is below
// 1e-9 (test::wormhole_scene: a static observer at l, this side's sky 0.25,
// the other's 0.75).
template <class S>
SceneIn<S> wormhole_scene(const S& st, double l, ShotResources& res) {
  return test::wormhole_scene(st, l, res, 2000.0);
}
using test::traced;

// At angle alpha from the eye's -e_l leg (towards the throat where l > 0),
// in two planes.
std::vector<Vec3> at_angle(double alpha, double towards) {
  return {{towards * std::cos(alpha), std::sin(alpha), 0.0}, {towards * std::cos(alpha), 0.0, -std::sin(alpha)}};
}

// A ray from l with impact parameter h = r(l) sin α passes the throat iff h
// is below the least r, the throat's (Ellis: b; Interstellar: the
// cylinder's ρ), since (dl/dλ)^2 = E^2 - L^2/r(l)^2 turns back only where
// r(l) = h.  So the other sky fills a disc of angular radius
// arcsin(r_min / r(l)); rays at 0.99 and 1.01 of it fall either side (the
// tolerance moves the edge by far less), from this side and from the other.
template <class S>
void expect_throat_edge(const S& st, double r_min, double l, double r_at_l) {
  ShotResources res;
  const SceneIn<S> sc = wormhole_scene(st, l, res);
  const double towards = l > 0 ? -1.0 : 1.0;  // e_l points to larger l
  const std::size_t here = l > 0 ? 0 : 1, there = 1 - here;
  const double edge = std::asin(r_min / r_at_l);
  for (double f : {0.0, 0.5, 0.99})
    for (const RaySample& s : traced(sc, at_angle(f * edge, towards))) {
      EXPECT_EQ(s.hit.kind, HitKind::sky) << f;
      EXPECT_EQ(s.hit.spacetime_end, there) << f << " at l = " << l;
    }
  for (double f : {1.01, 1.5, 3.0})
    for (const RaySample& s : traced(sc, at_angle(f * edge, towards)))
      EXPECT_EQ(s.hit.spacetime_end, here) << f << " at l = " << l;
}

TEST(MorrisThorne, TheThroatsEdgeIsWhereTheImpactParameterIsTheLeastRadius) {
  for (double l : {3.0, 12.0, -6.0}) expect_throat_edge(EllisWormhole({1.0}), 1.0, l, ellis_r(1.0, l));
  const InterstellarWormhole film({1.0, 0.01, 0.05}), long_one({1.0, 4.0, 0.5});
  for (double l : {4.0, -10.0}) expect_throat_edge(film, 1.0, l, interstellar_r(1.0, 0.005, 0.05, l));
  for (double l : {8.0, -3.0}) expect_throat_edge(long_one, 1.0, l, interstellar_r(1.0, 2.0, 0.5, l));
}

// The exact deflection of a ray of impact parameter h > b past an Ellis
// throat: 2 ∫ h dl / (r √(r^2 - h^2)) from the turning point, less π, is
// 2K(b/h) - π (K the complete elliptic integral of the first kind).  From a
// static observer at l = 1000 (where space is flat to b^2/l^2 = 1e-6, and
// the bending still to come is ~1e-9) the ray's sky direction makes that
// angle with its first direction, within 2e-6 rad: the integrator's
// tolerance over the pass and the l = 1000 start's 1e-6.
TEST(MorrisThorne, EllisDeflectionIsTheEllipticIntegral) {
  ShotResources res;
  const EllisWormhole st({1.0});
  const double l0 = 1000.0;
  const SceneIn<EllisWormhole> sc = wormhole_scene(st, l0, res);
  for (double h : {1.2, 2.0, 5.0}) {
    const double alpha = std::asin(h / ellis_r(1.0, l0));
    const Vec3 dir = {-std::cos(alpha), std::sin(alpha), 0.0};
    const RaySample s = traced(sc, {dir})[0];
    ASSERT_EQ(s.hit.spacetime_end, 0) << h;
    // The first direction in the chart (isotropic: the legs' directions).
    Vec3 d0{};
    for (int a = 1; a < 4; ++a)
      for (int k = 0; k < 3; ++k) d0[k] += dir[a - 1] * sc.eye.frame.e[a][k + 1];
    const double n0 = norm3(d0);
    const Vec3 d1 = {std::sin(s.hit.sky_theta) * std::cos(s.hit.sky_phi),
                     std::sin(s.hit.sky_theta) * std::sin(s.hit.sky_phi), std::cos(s.hit.sky_theta)};
    const double turned = std::acos(std::clamp(dot3(d0, d1) / n0, -1.0, 1.0));
    EXPECT_NEAR(turned, 2 * std::comp_ellint_1(1.0 / h) - pi, 2e-6) << h;
  }
}

// Straight in along the axis: through the throat and out into the other
// universe with its direction kept (the other sky is read through an
// orientation-preserving map, so it is not mirrored): a ray leaving along
// -x here arrives along -x there, and one just off the axis to +y stays off
// it to +y.
TEST(MorrisThorne, ARayThroughTheThroatKeepsItsDirection) {
  ShotResources res;
  const SceneIn<EllisWormhole> sc = wormhole_scene(EllisWormhole({1.0}), 10.0, res);
  const std::vector<RaySample> s = traced(sc, {{-1.0, 0.0, 0.0}, {-std::cos(0.01), std::sin(0.01), 0.0}});
  for (const RaySample& r : s) EXPECT_EQ(r.hit.spacetime_end, 1);
  EXPECT_NEAR(s[0].hit.sky_theta, pi / 2, 1e-6);
  EXPECT_NEAR(std::cos(s[0].hit.sky_phi), -1.0, 1e-9);
  // e_θ at (90°, 0) is -z, e_φ is +y: the second ray leans to +y, and so
  // does its arrival (sin φ > 0 near φ = π).
  EXPECT_GT(std::sin(s[1].hit.sky_phi), 0.0);
}

// An object beyond the throat reaches as far as it is from the throat in
// |l|, the flight measure, however small its chart radius: so the
// free-flight radius clears it and rays meet it.
TEST(MorrisThorne, ReachIsInTheFlightMeasure) {
  const EllisWormhole st({1.0});
  ShotResources res;
  SphereParams p;
  p.radius = 1.0;
  p.placement.at = Vec4{0.0, -10.0, 0.5 * pi, 0.0};
  const Sphere beyond(p, st, res, st.trace_from_scene({0.0, 10.0, 0.5 * pi, 0.0}));
  const double reach = beyond.reach(st);
  EXPECT_GT(reach, 10.5);
  EXPECT_LT(reach, 12.0);
  EXPECT_EQ(st.flight_reach(0.0, 1.0), std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(st.flight_reach(0.5, 2.0), std::max(std::abs(st.proper_distance(0.5)), st.proper_distance(2.0)));
  // Kerr's measure is its chart radius, as before.
  EXPECT_EQ(Kerr(1.0, 0.5).flight_reach(3.0, 7.0), 7.0);
}

TEST(MorrisThorne, BadInputIsRefusedWithTheReason) {
  const auto message = [](auto make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] { EllisWormhole({0.0}); }).find("throat must be a finite number > 0"), std::string::npos);
  EXPECT_NE(message([] { EllisWormhole({-1.0}); }).find("got -1"), std::string::npos);
  EXPECT_NE(message([] { EllisWormhole({std::nan("")}); }).find("ellis_wormhole"), std::string::npos);
  EXPECT_NE(message([] { InterstellarWormhole({0.0, 0.1, 0.1}); }).find("throat must be > 0"), std::string::npos);
  EXPECT_NE(message([] { InterstellarWormhole({1.0, -0.1, 0.1}); }).find("length must be >= 0"), std::string::npos);
  EXPECT_NE(message([] { InterstellarWormhole({1.0, 0.1, 0.0}); }).find("lensing_width must be > 0"), std::string::npos);
  EXPECT_NE(message([] { InterstellarWormhole({1.0, INFINITY, 0.1}); }).find("finite"), std::string::npos);
}

}  // namespace
}  // namespace lc
