// Observer frames: orthonormal in the metric at many points (on the spin axis
// too), continuous onto the axis, boosts that preserve orthonormality, and
// refusals where an observer cannot exist.

#include <gtest/gtest.h>

#include "eye/tetrad.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {
namespace {

template <class S>
void expect_orthonormal(const S& st, const Vec4& x, const Tetrad& t, double tol = 1e-12) {
  const Mat4 g = st.metric(x);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const double eta = a == b ? (a == 0 ? -1.0 : 1.0) : 0.0;
      EXPECT_NEAR(contract(g, t.e[a], t.e[b]), eta, tol) << "legs " << a << b;
    }
}

TEST(Tetrad, StaticAndZamoFramesAreOrthonormal) {
  const Kerr k(1.0, 0.9);
  for (double r : {3.0, 6.0, 30.0})
    for (double th : {0.0, 0.3, 1.2, 1.5707963267948966, 3.141592653589793})
      for (double ph : {0.0, 2.0}) {
        const Vec4 s = {0, r, th, ph};
        const Vec4 x = k.trace_from_scene(s);
        expect_orthonormal(k, x, static_polar_tetrad(k, s));
        expect_orthonormal(k, x, zamo_polar_tetrad(k, s));
      }
}

TEST(Tetrad, StaticFrameOnTheAxisIsTheLimitOfNearbyFrames) {
  // docs/architecture.md: on the axis the frame is the limit at the observer's phi, so an
  // inclination sweep from 0 is continuous.
  const Kerr k(1.0, 0.9);
  const Tetrad on = static_polar_tetrad(k, {0, 30, 0.0, 0.7});
  const Tetrad near = static_polar_tetrad(k, {0, 30, 1e-7, 0.7});
  for (int a = 0; a < 4; ++a)
    for (int m = 0; m < 4; ++m) EXPECT_NEAR(on.e[a][m], near.e[a][m], 1e-5) << a << m;
}

TEST(Tetrad, FlatStaticFrameIsTheSphericalUnitFrame) {
  const Kerr flat(0.0, 0.0);
  const double th = 0.8, ph = 0.3;
  const Tetrad t = static_polar_tetrad(flat, {0, 10, th, ph});
  const Vec4 er = {0, std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)};
  const Vec4 eth = {0, std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), -std::sin(th)};
  const Vec4 eph = {0, -std::sin(ph), std::cos(ph), 0};
  for (int m = 0; m < 4; ++m) {
    EXPECT_NEAR(t.e[1][m], er[m], 1e-14);
    EXPECT_NEAR(t.e[2][m], eth[m], 1e-14);
    EXPECT_NEAR(t.e[3][m], eph[m], 1e-14);
  }
}

TEST(Tetrad, ZamoHasZeroAngularMomentum) {
  const Kerr k(1.0, 0.9);
  const Vec4 s = {0, 4.0, 1.0, 0.5};
  const Vec4 x = k.trace_from_scene(s);
  const Tetrad z = zamo_polar_tetrad(k, s);
  const Vec4 u_low = mat_vec(k.metric(x), z.e[0]);
  // L_z = u_phi = u_mu (∂_phi)^mu, with ∂_phi = (0, -y, x, 0) in Kerr–Schild.
  EXPECT_NEAR(-x[2] * u_low[1] + x[1] * u_low[2], 0.0, 1e-12);
}

TEST(Tetrad, BoostedFrameIsOrthonormalAndMovesWithV) {
  const Kerr k(1.0, 0.5);
  const Vec4 s = {0, 8, 1.0, 0.0};
  const Vec4 x = k.trace_from_scene(s);
  const Tetrad rest = static_polar_tetrad(k, s);
  const Vec3 v = {0.3, -0.2, 0.6};
  const Tetrad moving = boost(rest, v);
  expect_orthonormal(k, x, moving, 1e-12);
  const Vec3 back = relative_velocity(k.metric(x), rest, moving.e[0]);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], v[i], 1e-12);
  EXPECT_THROW(boost(rest, {0.8, 0.6, 0.0}), ObserverError);
}

TEST(Tetrad, FromAGivenFourVelocity) {
  const Kerr k(1.0, 0.7);
  const Vec4 s = {0, 9, 1.2, 0.4};
  const Tetrad moving = boost(static_polar_tetrad(k, s), {0.1, 0.2, -0.3});
  const Tetrad t = tetrad_from_velocity(k, s, moving.e[0]);
  for (int a = 0; a < 4; ++a)
    for (int m = 0; m < 4; ++m) EXPECT_NEAR(t.e[a][m], moving.e[a][m], 1e-12);
}

TEST(Tetrad, RefusesObserversThatCannotExist) {
  const Kerr k(1.0, 0.9);
  EXPECT_THROW(static_polar_tetrad(k, {0, 1.2, 1.0, 0.0}), ObserverError);          // inside horizon
  EXPECT_THROW(static_polar_tetrad(k, {0, 1.8, 1.5707963, 0.0}), ObserverError);    // ergoregion (r < 2 at equator)
  EXPECT_NO_THROW(zamo_polar_tetrad(k, {0, 1.8, 1.5707963, 0.0}));                   // ZAMOs exist there
  const Dihole d(0.4, 0.4, 1.0);
  EXPECT_THROW(static_cartesian_tetrad(d, {0, 0, 0, 1.001}), ObserverError);
  expect_orthonormal(d, {0, 5, 0, 0}, static_cartesian_tetrad(d, Vec4{0, 5, 0, 0}));
}

}  // namespace
}  // namespace lc
