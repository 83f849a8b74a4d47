// lc.circular_orbit (observers/circular_orbit.hpp) against closed forms:
// Kepler's angular velocity in Schwarzschild, Kerr–Newman's, and the
// dihole's from its potential; its clock's rate u^t = 1/sqrt(1 - 3M/r);
// its frame orthonormal, moving with the orbit and keeping e_r; its place
// a period later; and clear refusals where no orbit exists.

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/constants.hpp"
#include "observers/observers.hpp"
#include "render/scene_builder.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"

namespace lc {
namespace {

CircularOrbit::Params orbit(double r, double phi_deg = 0.0, double t = 0.0) {
  CircularOrbit::Params p;
  p.r = r;
  p.phi = phi_deg;
  p.t = t;
  p.where = "shot.lua:7";
  return p;
}

// The observer's eye dt after the frame's moment as the scene builder
// makes it in the spacetime S.
template <class S>
Eye eye_of(const S& st, const CircularOrbit::Params& p, double dt = 0.0) {
  SceneSpec fs;
  fs.spacetime = st;
  fs.observer = p;
  ShotResources res;
  return scene_get<S>(build_scene(fs, 4, 4, res)).observer_path.at(dt);
}

TEST(CircularOrbit, SchwarzschildKeplerAndItsClock) {
  // Omega = sqrt(M / r^3) in Schwarzschild time, dt/dtau = 1 / sqrt(1 - 3M/r).
  const Kerr hole(1.0, 0.0);
  const Kerr st = trace_chart(hole).get<Kerr>();
  ShotResources res;
  for (double r : {6.0, 10.0, 25.0}) {
    const CircularOrbit o(orbit(r), st, res);
    EXPECT_NEAR(o.angular_velocity(), std::sqrt(1.0 / (r * r * r)), 1e-14) << r;
    const Eye e = eye_of(hole, orbit(r));
    const Vec4 u = st.scene_vector(e.event, e.frame.e[0]);
    EXPECT_NEAR(u[0], 1 / std::sqrt(1 - 3 / r), 1e-12) << r;
    EXPECT_NEAR(u[1], 0.0, 1e-12);
    EXPECT_NEAR(u[3] / u[0], std::sqrt(1.0 / (r * r * r)), 1e-12);
  }
}

TEST(CircularOrbit, KerrNewmanAngularVelocity) {
  // Omega = sqrt(M r - Q^2) / (r^2 + a sqrt(M r - Q^2)), co-rotating.
  for (auto [a, q] : {std::pair{0.5, 0.6}, {0.9, 0.0}, {-0.7, 0.3}}) {
    const Kerr st = trace_chart(Kerr(1.0, a, q)).get<Kerr>();
    ShotResources res;
    for (double r : {8.0, 15.0}) {
      const double s = std::sqrt(r - q * q);
      const double expected = (a < 0 ? -1 : 1) * s / (r * r + std::abs(a) * s);
      EXPECT_NEAR(CircularOrbit(orbit(r), st, res).angular_velocity(), expected, 1e-13) << a << " " << q << " " << r;
    }
  }
}

TEST(CircularOrbit, ItsFrameMovesWithItAndKeepsTheRadialLeg) {
  const Kerr hole(1.0, 0.9, 0.3);
  const Kerr st = trace_chart(hole).get<Kerr>();
  const Vec4 s = {0.0, 9.0, 0.5 * pi, 0.4};
  const Eye e = eye_of(hole, orbit(9.0, 0.4 / degree));
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(e.scene_event[k], s[k], 1e-12) << k;
  // Orthonormal in the metric, e0 the disk's matter there.
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      double g = 0;
      for (int m = 0; m < 4; ++m)
        for (int n = 0; n < 4; ++n) g += e.metric[m][n] * e.frame.e[a][m] * e.frame.e[b][n];
      EXPECT_NEAR(g, a != b ? 0.0 : a == 0 ? -1.0 : 1.0, 1e-12) << a << b;
    }
  const Vec4 u = st.disk_velocity(e.event);
  for (int m = 0; m < 4; ++m) EXPECT_NEAR(e.frame.e[0][m], u[m], 1e-12);
  // The boost along e_phi leaves the static frame's e_r: the camera looking
  // at the hole (forward = -e_r) still does.
  const Tetrad rest = static_polar_tetrad(st, s);
  for (int m = 0; m < 4; ++m) EXPECT_NEAR(e.frame.e[1][m], rest.e[1][m], 1e-12);
}

TEST(CircularOrbit, APeriodLaterItIsBackWhereItWas) {
  // Stationary and axisymmetric: after 2 pi / Omega of scene time the eye is
  // at the same place with the same frame; a quarter period on, a quarter
  // turn further; and the scene's time moves it as the offset does.
  const Kerr hole(1.0, 0.6, 0.5);
  const Kerr st = trace_chart(hole).get<Kerr>();
  ShotResources res;
  const double omega = CircularOrbit(orbit(12.0, 30.0, 5.0), st, res).angular_velocity();
  const double period = 2 * pi / omega;
  const Eye now = eye_of(hole, orbit(12.0, 30.0, 5.0));
  const Eye back = eye_of(hole, orbit(12.0, 30.0, 5.0), period);
  EXPECT_NEAR(back.time, now.time + period, 1e-9);
  for (int k = 1; k < 4; ++k) EXPECT_NEAR(back.event[k], now.event[k], 1e-9) << k;
  for (int a = 0; a < 4; ++a)
    for (int m = 1; m < 4; ++m) EXPECT_NEAR(back.frame.e[a][m], now.frame.e[a][m], 1e-9) << a << m;
  const Eye quarter = eye_of(hole, orbit(12.0, 30.0, 5.0), 0.25 * period);
  EXPECT_NEAR(quarter.scene_event[3], 30 * degree + omega * 5.0 + 0.5 * pi, 1e-12);
  const Eye later = eye_of(hole, orbit(12.0, 30.0, 5.0 + 0.25 * period));
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(later.scene_event[k], quarter.scene_event[k], 1e-12) << k;
}

TEST(CircularOrbit, BetweenTwoEqualHolesItOrbitsTheAxis) {
  // In the dihole's plane z = 0 between equal masses m at z = +-d:
  // U = 1 + 2m / sqrt(R^2 + d^2), and a circular geodesic has
  // Omega^2 = -d_R g_tt / d_R g_phiphi with g_tt = -U^-2, g_phiphi = U^2 R^2.
  const double m = 0.4, d = 1.0, R = 6.0;
  const Dihole st(m, m, d);
  const double w = std::sqrt(R * R + d * d);
  const double U = 1 + 2 * m / w, UR = -2 * m * R / (w * w * w);
  const double expected = std::sqrt(-(2 * UR / (U * U * U)) / (2 * U * UR * R * R + 2 * U * U * R));
  ShotResources res;
  EXPECT_NEAR(CircularOrbit(orbit(R), st, res).angular_velocity(), expected, 1e-12);
}

TEST(CircularOrbit, WhereNoOrbitIsItSaysSo) {
  ShotResources res;
  auto message = [&](auto&& make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const Kerr st = trace_chart(Kerr(1.0, 0.0)).get<Kerr>();
  EXPECT_EQ(message([&] { CircularOrbit(orbit(5.0), st, res); }),
            "shot.lua:7: observer: no circular orbit at r = 5 in kerr (inside the innermost stable one a disk's "
            "matter plunges; between two holes it may be none at all); put it farther out");
  EXPECT_NE(message([&] { CircularOrbit(orbit(10.0), Minkowski{}, res); })
                .find("shot.lua:7: observer: lightcone has no circular orbits in minkowski"),
            std::string::npos);
  EXPECT_NE(message([&] { CircularOrbit(orbit(2.1), st, res); }).find("too close to a horizon"), std::string::npos);
}

}  // namespace
}  // namespace lc
