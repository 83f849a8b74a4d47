// Majumdar–Papapetrou spacetimes of N extreme Reissner–Nordström holes
// (spacetime/majumdar_papapetrou.hpp) against figures known independently:
// two holes on the z axis are the dihole, to rounding and in the paper's
// oscillation period; U is harmonic (the Einstein–Maxwell equations for this
// metric, so any placement is static: masses at rest stay at rest); a body
// at a symmetric point stays there; a body on the axis of a triangle of
// holes swings through it with the period of the energy integral.  The
// generic self-test (spacetime_test.cpp) checks the metric against its
// numerical derivatives on MajumdarPapapetrou::examples().

#include <gtest/gtest.h>

#include <gsl/gsl_integration.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "core/lanes.hpp"
#include "eye/tetrad.hpp"
#include "geodesic/geodesic_solver.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/majumdar_papapetrou.hpp"
#include "test_points.hpp"
#include "test_scenes.hpp"

namespace lc {
namespace {

MajumdarPapapetrou holes(std::initializer_list<PointHole> list) {
  MajumdarPapapetrou::Params p;
  for (const PointHole& h : list) p.holes.add(h);
  return MajumdarPapapetrou(p);
}

// Three holes of mass m at distance R from the z axis in the plane z = 0.
MajumdarPapapetrou triangle(double m, double R) {
  const double s = std::sqrt(3.0) / 2.0;
  return holes({{m, {R, 0.0, 0.0}}, {m, {-0.5 * R, s * R, 0.0}}, {m, {-0.5 * R, -s * R, 0.0}}});
}

// Four holes of mass m at the corners (+-a, +-a, 0) of a square.
MajumdarPapapetrou square(double m, double a) {
  return holes({{m, {a, a, 0.0}}, {m, {-a, a, 0.0}}, {m, {-a, -a, 0.0}}, {m, {a, -a, 0.0}}});
}

// A triangle and a square of holes, in a vector: GCC 12 at -O3 reads an
// initializer list of them with aligned vector loads from a backing array it
// has not aligned (a crash in a range-for over {triangle(..), square(..)};
// clean under -O2 and the sanitizers).
std::vector<MajumdarPapapetrou> triangle_and_square() { return {triangle(0.3, 1.0), square(0.25, 1.0)}; }

std::string message_of(const MajumdarPapapetrou::Params& p) {
  try {
    MajumdarPapapetrou st(p);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return {};
}

// Two holes on the z axis are the dihole: the same U, gradient, Hamilton's
// equations and far field.  To 1e-14 relative, not bit for bit: the general
// sum rounds differently ((c1 + c2) x against c1 x + c2 x).
TEST(MajumdarPapapetrou, TwoHolesOnTheAxisAreTheDihole) {
  for (const auto& [m1, m2, d] : {std::tuple{0.4, 0.4, 1.0}, std::tuple{0.6, 0.2, 1.5}}) {
    const Dihole di(m1, m2, d);
    const MajumdarPapapetrou mp = holes({{m1, {0.0, 0.0, d}}, {m2, {0.0, 0.0, -d}}});
    EXPECT_DOUBLE_EQ(mp.asymptotic_mass(), di.asymptotic_mass());
    EXPECT_NEAR(mp.far_field_radius(), di.far_field_radius(), 1e-12 * di.far_field_radius());
    EXPECT_NEAR(mp.photon_reach(), di.photon_reach(), 1e-14 * di.photon_reach());
    const auto pts = test::cartesian_points(200, 0.3, 50.0);
    const auto ps = test::momenta(static_cast<int>(pts.size()));
    for (std::size_t i = 0; i < pts.size(); ++i) {
      Vec3 ga, gb;
      const double ua = di.potential(pts[i], &ga), ub = mp.potential(pts[i], &gb);
      EXPECT_NEAR(ub, ua, 1e-14 * ua);
      const double gn = norm3(ga);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(gb[k], ga[k], 1e-14 * gn + 1e-300);
      std::array<double, 8> y{}, da{}, db{};
      for (int c = 0; c < 4; ++c) y[c] = pts[i][c], y[4 + c] = ps[i][c];
      di.rhs(y, da);
      mp.rhs(y, db);
      for (int c = 0; c < 8; ++c) EXPECT_NEAR(db[c], da[c], 1e-13 * (std::abs(da[c]) + 1e-12)) << "component " << c;
    }
  }
}

// The paper's sphere, released at rest at (5, 0, 0) between two holes of
// 0.4 at z = +-1, has the period Wünsch et al. (2013) give (110.594 in
// coordinate time, 78.753 proper; geodesic_solver_test.cpp holds the
// dihole's to the same figures).
TEST(MajumdarPapapetrou, TwoHolesOnTheAxisSwingTheDiholesSphere) {
  GeodesicProblem pb = test::dihole_oscillation_problem(StopParameter::coordinate_time, 112.0);
  const MajumdarPapapetrou mp = holes({{0.4, {0.0, 0.0, 1.0}}, {0.4, {0.0, 0.0, -1.0}}});
  pb.spacetime = mp;
  pb.u0 = static_cartesian_tetrad(mp, pb.x0).e[0];
  pb.samples = 11201;
  const GeodesicPath path = solve_geodesic(pb);
  ASSERT_EQ(path.reason, StopReason::reached);
  const auto [T, tau] = test::turn_after(path, 1, 50.0);
  EXPECT_NEAR(T, 110.594, 1e-3);
  EXPECT_NEAR(tau, 78.753, 1e-3);
}

// The metric solves the Einstein–Maxwell equations exactly where U is
// harmonic away from the holes (Hartle & Hawking 1972): with one term
// 1/|x - x_i| per hole it is for any placement, which is why the holes stay
// at rest wherever they are put.  The Laplacian by central differences with
// h = 1e-3 rho (rho: the distance to the nearest hole, at most 1): the
// truncation, ~h^2 |U''''| / 12 ~ 2 (h / rho)^2 |U''|, stays below 2e-6 of
// the second derivatives' sizes; the rounding of U's values, ~16 eps U / h^2,
// is added.
TEST(MajumdarPapapetrou, ThePotentialIsHarmonic) {
  for (const MajumdarPapapetrou& mp : triangle_and_square()) {
    for (const Vec4& x : test::cartesian_points(100, 1.6, 20.0)) {
      double rho = 1.0;
      for (const PointHole& hole : mp.holes())
        rho = std::min(rho, norm3({x[1] - hole.position[0], x[2] - hole.position[1], x[3] - hole.position[2]}));
      const double h = 1e-3 * rho, u0 = mp.potential(x);
      double lap = 0.0, scale = 0.0;
      for (int k = 1; k <= 3; ++k) {
        Vec4 a = x, b = x;
        a[k] += h;
        b[k] -= h;
        const double second = (mp.potential(a) - 2.0 * u0 + mp.potential(b)) / (h * h);
        lap += second;
        scale += std::abs(second);
      }
      const double rounding = 16.0 * 2.3e-16 * u0 / (h * h);
      EXPECT_LT(std::abs(lap), 2e-6 * scale + rounding) << "at " << x[1] << ", " << x[2] << ", " << x[3];
    }
  }
}

// A body at rest where the pulls cancel by symmetry (the centre of a
// triangle, of a square) stays there.  The balance is unstable (U, being
// harmonic, has saddles, not minima: pushed along the plane the body falls
// towards a hole), so the rounding of the triangle's corners (sqrt(3)/2)
// grows about e-fold per 4 M of proper time: for 20 M it stays within 1e-12.
TEST(MajumdarPapapetrou, ABodyAtTheCentreOfSymmetryStaysThere) {
  for (const MajumdarPapapetrou& mp : triangle_and_square()) {
    GeodesicProblem pb;
    pb.spacetime = mp;
    pb.kind = CurveKind::timelike;
    pb.x0 = {0.0, 0.0, 0.0, 0.0};
    pb.u0 = static_cartesian_tetrad(mp, pb.x0).e[0];
    pb.stop_parameter = StopParameter::proper_time;
    pb.stop_value = 20.0;
    pb.samples = 21;
    const GeodesicPath path = solve_geodesic(pb);
    ASSERT_EQ(path.reason, StopReason::reached);
    for (const GeodesicSample& s : path.samples)
      for (int k = 1; k <= 3; ++k) EXPECT_NEAR(s.x[k], 0.0, 1e-12);
  }
}

// A body released at rest on the axis of a triangle of holes (at z0 = 3,
// holes of 0.3 at distance 1) falls through the centre to -z0 and back.
// Along the axis U(z) = 1 + 3m / sqrt(1 + z^2), the energy E = U^-2 dt/dtau
// = 1/U(z0) is conserved and U^2 (dz/dtau)^2 = E^2 U^2 - 1, so the period is
// T = 4 ∫_0^z0 E U^3 / sqrt(E^2 U^2 - 1) dz in coordinate time and
// 4 ∫_0^z0 U / sqrt(E^2 U^2 - 1) dz proper, by adaptive Gauss–Kronrod (GSL
// QAGS, which does not evaluate the integrable endpoint) to 1e-11.  The
// integrator (rk8pd at 1e-12), sampled every 0.005 M, finds the return to
// z0 to 1e-6 and the lowest point to 1e-7 (a sample lies within 0.0025 M
// of it: ~|z''| 0.0025^2 / 2 < 1e-7).
TEST(MajumdarPapapetrou, ABodyOnTheTrianglesAxisSwingsWithTheEnergyIntegralsPeriod) {
  const double m = 0.3, z0 = 3.0;
  const MajumdarPapapetrou mp = triangle(m, 1.0);
  struct Axis {
    double m, E;
    bool proper;
  };
  auto integrand = [](double z, void* p) {
    const auto& a = *static_cast<const Axis*>(p);
    const double U = 1.0 + 3.0 * a.m / std::sqrt(1.0 + z * z);
    const double root = std::sqrt(a.E * a.E * U * U - 1.0);
    return a.proper ? U / root : a.E * U * U * U / root;
  };
  auto period = [&](bool proper) {
    Axis a{m, 1.0 / (1.0 + 3.0 * m / std::sqrt(1.0 + z0 * z0)), proper};
    gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
    gsl_function f{+integrand, &a};
    double value = 0.0, error = 0.0;
    gsl_integration_qags(&f, 0.0, z0, 0.0, 1e-11, 1000, w, &value, &error);
    gsl_integration_workspace_free(w);
    return 4.0 * value;
  };
  const double T = period(false), tau = period(true);

  GeodesicProblem pb;
  pb.spacetime = mp;
  pb.kind = CurveKind::timelike;
  pb.x0 = {0.0, 0.0, 0.0, z0};
  pb.u0 = static_cartesian_tetrad(mp, pb.x0).e[0];
  pb.stop_parameter = StopParameter::coordinate_time;
  pb.stop_value = 1.1 * T;
  pb.samples = static_cast<int>(pb.stop_value / 0.005) + 1;
  const GeodesicPath path = solve_geodesic(pb);
  ASSERT_EQ(path.reason, StopReason::reached);
  double zmin = z0;
  for (const GeodesicSample& b : path.samples) {
    zmin = std::min(zmin, b.x[3]);
    EXPECT_NEAR(b.x[1], 0.0, 1e-12);
    EXPECT_NEAR(b.x[2], 0.0, 1e-12);
  }
  const auto [found_T, found_tau] = test::turn_after(path, 3, 0.75 * T);
  EXPECT_NEAR(zmin, -z0, 1e-7);
  EXPECT_NEAR(found_T, T, 1e-6 * T);
  EXPECT_NEAR(found_tau, tau, 1e-6 * tau);
  RecordProperty("period", std::to_string(T));
}

TEST(MajumdarPapapetrou, BadHolesAreRefusedWithTheReason) {
  MajumdarPapapetrou::Params p;
  EXPECT_NE(message_of(p).find("give at least one hole"), std::string::npos) << message_of(p);
  p.holes.add({0.5, {0.0, 0.0, 0.0}});
  p.holes.add({0.0, {2.0, 0.0, 0.0}});
  EXPECT_NE(message_of(p).find("hole 2's mass must be a number > 0, got 0"), std::string::npos) << message_of(p);
  p.holes.holes[1].mass = -0.1;
  EXPECT_NE(message_of(p).find("hole 2's mass must be a number > 0, got -0.1"), std::string::npos) << message_of(p);
  p.holes.holes[1] = {0.5, {0.05, 0.0, 0.0}};
  EXPECT_NE(message_of(p).find("holes 1 and 2 are 0.05 apart, inside each other's capture spheres"), std::string::npos)
      << message_of(p);
  p.holes.holes[1] = {0.5, {0.0, 0.0, 0.0}};
  EXPECT_NE(message_of(p).find("holes 1 and 2 are 0 apart"), std::string::npos) << message_of(p);
  p.holes.holes[1] = {0.5, {std::nan(""), 0.0, 0.0}};
  EXPECT_NE(message_of(p).find("hole 2's position must be finite numbers"), std::string::npos) << message_of(p);
  p.holes.holes[1] = {0.5, {1.0, 0.0, 0.0}};
  EXPECT_EQ(message_of(p), "");
}

}  // namespace
}  // namespace lc
