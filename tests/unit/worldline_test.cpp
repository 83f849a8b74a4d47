// Worldlines integrated once per shot and sampled by proper or coordinate
// time must agree with the reference solver sampled directly.

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "geodesic/geodesic_solver.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"
#include "test_scenes.hpp"
#include "worldline/worldline.hpp"

namespace lc {
namespace {

WorldlineSpec dihole_oscillation() {
  WorldlineSpec w;
  w.spacetime = Dihole(0.4, 0.4, 1.0);
  w.start = {0, 5, 0, 0};
  w.duration = 100;
  w.where = "test";
  return w;
}

TEST(Worldline, InterpolationMatchesTheReferenceSolver) {
  const Worldline w = Worldline::integrate(dihole_oscillation());
  for (double tau : {0.0, 12.345, 39.3765, 77.7, 100.0}) {
    const GeodesicProblem pb = test::dihole_oscillation_problem(StopParameter::proper_time, std::max(tau, 1e-9));
    const Vec4 ref = solve_geodesic(pb).samples.back().x;
    const WorldlineEvent ev = w.at_proper_time(tau);
    for (int m = 0; m < 4; ++m) EXPECT_NEAR(ev.x[m], ref[m], 1e-7) << "tau " << tau << " component " << m;
    // The interpolated frame is orthonormal and its time leg is the 4-velocity.
    const Mat4 g = Dihole(0.4, 0.4, 1.0).metric(ev.x);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        EXPECT_NEAR(contract(g, ev.frame.e[a], ev.frame.e[b]), a == b ? (a == 0 ? -1.0 : 1.0) : 0.0, 1e-10);
  }
}

TEST(Worldline, CoordinateTimeLookupInvertsProperTime) {
  const Worldline w = Worldline::integrate(dihole_oscillation());
  for (double t : {0.5, 30.0, 55.297, 110.0}) {
    const WorldlineEvent ev = w.at_coordinate_time(t);
    EXPECT_NEAR(ev.x[0], t, 1e-9);
    EXPECT_NEAR(w.at_proper_time(ev.tau).x[0], t, 1e-9);
  }
  // Half a period after release (T/2 = 55.297) the body is at x = -5.
  EXPECT_NEAR(w.at_coordinate_time(110.594 / 2).x[1], -5.0, 1e-4);
}

TEST(Worldline, CoordinateTimeLookupOfTheCentreMatchesTheReferenceSolver) {
  // The rays' centre lookups go through a table uniform in coordinate time
  // (position and 4-velocity each Hermite in t).  Against the reference
  // solver run to the same proper time, over a whole oscillation including
  // the fast passes between the holes: within 1e-7 (the proper-time
  // interpolant's own bound above), far below what a sphere's pixels show.
  const Worldline w = Worldline::integrate(dihole_oscillation());
  for (double t : {3.21, 27.0, 55.297, 61.5, 99.9, 110.3}) {
    Vec4 x, u;
    w.centre_at_coordinate_time(t, x, u);
    const GeodesicProblem pb = test::dihole_oscillation_problem(StopParameter::proper_time, w.at_coordinate_time(t).tau);
    const GeodesicSample ref = solve_geodesic(pb).samples.back();
    for (int m = 0; m < 4; ++m) {
      EXPECT_NEAR(x[m], ref.x[m], 1e-7) << "t " << t << " component " << m;
      EXPECT_NEAR(u[m], ref.u[m], 1e-7) << "t " << t << " component " << m;
    }
  }
}

TEST(Worldline, BeforeItsStartTheBodyRestsThere) {
  const Worldline w = Worldline::integrate(dihole_oscillation());
  const WorldlineEvent ev = w.at_coordinate_time(-20.0);
  EXPECT_EQ(ev.x[0], -20.0);
  EXPECT_EQ(ev.x[1], 5.0);
  EXPECT_EQ(ev.tau, 0.0);
}

TEST(Worldline, SpacetimeTubeBoundsThePath) {
  const Worldline w = Worldline::integrate(dihole_oscillation());
  Vec3 lo, hi;
  w.bounds(0.0, 110.594, lo, hi);  // a whole period: x spans [-5, 5]
  EXPECT_LE(lo[0], -4.999);
  EXPECT_GE(hi[0], 4.999);
  w.bounds(0.0, 1.0, lo, hi);  // the first moment: still near x = 5
  EXPECT_GT(lo[0], 4.5);
}

// The top coordinate speed bounds the centre's speed between table samples
// too (the reuse window divides by it), and is the exact one.  In the
// isotropic dihole (ds^2 = -dt^2/U^2 + U^2 dx^2) a body released at rest
// where U = U0 moves at beta = sqrt(1 - U0^2/U^2) past static observers
// (energy conservation), so at dx/dt = beta / U^2, largest where
// U^2 = 1.5 U0^2: 1 / (1.5 sqrt(3) U0^2).  Along the oscillation U runs
// from U0 = 1 + 0.8/sqrt(26) at (5, 0, 0) to 1.8 at the origin, past that.
TEST(Worldline, TopCoordinateSpeedBoundsTheMotion) {
  const Worldline w = Worldline::integrate(dihole_oscillation());
  double seen = 0.0;
  Vec4 x, u, x_prev;
  w.centre_at_coordinate_time(0.0, x_prev, u);
  const double dt = 1e-3;
  for (double t = dt; t < 110.594; t += dt) {
    w.centre_at_coordinate_time(t, x, u);
    seen = std::max(seen, std::hypot(x[1] - x_prev[1], x[2] - x_prev[2], x[3] - x_prev[3]) / dt);
    x_prev = x;
  }
  EXPECT_LE(seen, w.top_coordinate_speed());
  EXPECT_GT(seen, 0.999 * w.top_coordinate_speed());
  const double U0 = 1.0 + 0.8 / std::sqrt(26.0);
  EXPECT_NEAR(w.top_coordinate_speed(), 1.0 / (1.5 * std::sqrt(3.0) * U0 * U0), 1e-4);
}

// A fall into Kerr (a = 0.9) from r = 6, shown until just before the
// horizon: near it the trace chart (outgoing Kerr-Schild, singular at the
// future horizon) made the blended frame not timelike, and such frames were
// refused (issue 25, defect 9).  Every frame is orthonormal to 1e-9 (the
// frame is carried by the transport equations there) and lies on the
// reference solver's curve.
TEST(Worldline, AFallIsFramedUntilJustOutsideTheHorizon) {
  WorldlineSpec spec;
  const Kerr kerr(1.0, 0.9);
  spec.spacetime = kerr;
  spec.start = {0, 6, 60 * degree, 0};
  spec.velocity = {-0.5, 0, 0.3};
  spec.duration = 7.7;
  spec.where = "test";
  const Worldline w = Worldline::integrate(spec);
  const Kerr& st = w.spacetime().get<Kerr>();
  for (double tau = 7.40; tau <= 7.7; tau += 0.005) {
    const WorldlineEvent ev = w.at_proper_time(tau);
    const Mat4 g = st.metric(ev.x);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        EXPECT_NEAR(contract(g, ev.frame.e[a], ev.frame.e[b]), a == b ? (a == 0 ? -1.0 : 1.0) : 0.0, 1e-9)
            << "tau " << tau;
    EXPECT_GT(st.scene_from_trace(ev.x)[1], kerr.horizon_radius()) << "tau " << tau;
  }
}

// Inside the ergoregion no static observer exists; a worldline starting
// there takes its velocity relative to the ZAMO (at rest: the ZAMO's own).
TEST(Worldline, AFallMayStartInsideTheErgoregion) {
  WorldlineSpec spec;
  spec.spacetime = Kerr(1.0, 0.9);
  spec.start = {0, 1.9, 90 * degree, 0};
  spec.duration = 0.2;
  spec.where = "test";
  const Worldline w = Worldline::integrate(spec);
  const Kerr& st = w.spacetime().get<Kerr>();
  const Vec4 u = w.at_proper_time(0.0).frame.e[0];
  const Vec4 zamo = zamo_velocity(st, st.trace_from_scene(spec.start));
  for (int m = 0; m < 4; ++m) EXPECT_NEAR(u[m], zamo[m], 1e-12) << m;
}

TEST(Worldline, RefusesACaptureBeforeItsEnd) {
  WorldlineSpec w;
  w.spacetime = Kerr(1.0, 0.0);
  w.start = {0, 6, 1.5707963267948966, 0};
  w.duration = 500;  // at rest at r = 6: falls in long before
  w.where = "shot.lua:9";
  try {
    Worldline::integrate(w);
    FAIL() << "expected an error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("shot.lua:9: the worldline stopped early (horizon)"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace lc
