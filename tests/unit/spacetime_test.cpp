// Every spacetime against itself and against closed forms: metric times its
// inverse, analytic derivatives against finite differences, Hamilton's
// equations against finite differences of H, the Kerr–Schild form against the
// Boyer–Lindquist form through the coordinate map, and the special cases
// (a = 0 is Schwarzschild, M = 0 is flat), with and without a charge
// (Kerr–Newman, Reissner–Nordström).

#include <gtest/gtest.h>

#include "objects/disk_physics.hpp"
#include "spacetime/spacetime.hpp"
#include "test_points.hpp"

namespace lc {
namespace {

// Central differences with step h have truncation error ~h^2 f''' and
// round-off ~eps f / h; h = 1e-5 balances them near 1e-10 for O(1) metrics,
// so comparisons below use 1e-7, relative to the derivative where it is
// larger than one (near a dihole's point horizon derivatives reach ~100).
constexpr double fd_step = 1e-5;
constexpr double fd_tol = 1e-7;

template <class S>
void expect_inverse(const S& st, const std::vector<Vec4>& pts) {
  for (const auto& x : pts) {
    const Mat4 I = multiply(st.metric(x), st.inverse_metric(x));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) EXPECT_NEAR(I[i][j], i == j ? 1.0 : 0.0, 1e-12) << "at x=" << x[1] << "," << x[2] << "," << x[3];
  }
}

template <class S>
void expect_derivatives(const S& st, const std::vector<Vec4>& pts) {
  for (const auto& x : pts) {
    const Mat4Derivs d = st.metric_derivatives(x);
    for (int a = 0; a < 4; ++a) {
      Vec4 xp = x, xm = x;
      xp[a] += fd_step;
      xm[a] -= fd_step;
      const Mat4 gp = st.metric(xp), gm = st.metric(xm);
      for (int m = 0; m < 4; ++m)
        for (int n = 0; n < 4; ++n)
          EXPECT_NEAR(d[a][m][n], (gp[m][n] - gm[m][n]) / (2 * fd_step), fd_tol * std::max(1.0, std::abs(d[a][m][n])))
              << "d" << a << " g" << m << n << " at " << x[1] << "," << x[2] << "," << x[3];
    }
  }
}

template <class S>
double hamiltonian(const S& st, const Vec4& x, const Vec4& p) {
  return 0.5 * contract(st.inverse_metric(x), p, p);
}

template <class S>
void expect_hamilton_equations(const S& st, const std::vector<Vec4>& pts) {
  const auto ps = test::momenta(static_cast<int>(pts.size()));
  for (std::size_t k = 0; k < pts.size(); ++k) {
    const Vec4& x = pts[k];
    const Vec4& p = ps[k];
    Vec4 dx, dp;
    st.hamiltonian_rhs(x, p, dx, dp);
    const Vec4 dx_ref = mat_vec(st.inverse_metric(x), p);
    for (int m = 0; m < 4; ++m) {
      EXPECT_NEAR(dx[m], dx_ref[m], 1e-12);
      Vec4 xp = x, xm = x;
      xp[m] += fd_step;
      xm[m] -= fd_step;
      const double dH = (hamiltonian(st, xp, p) - hamiltonian(st, xm, p)) / (2 * fd_step);
      EXPECT_NEAR(dp[m], -dH, fd_tol * std::max(1.0, std::abs(dp[m]))) << "component " << m;
    }
  }
}

// The chart maps at trace events x: scene_from_trace undone by
// trace_from_scene (to 1e-9 of the event's size: Kerr's maps go through
// logarithms and an inverse quartic); scene_vector and scene_time_gradient
// against central differences of scene_from_trace (step 1e-5 along a unit
// vector, less near the axis: truncation ~1e-10, bound 1e-6 relative, plus
// the coordinates' rounding over the step).
// And the disk's matter in the equatorial plane (where x's cylindrical
// radius is at least r_min): a future-pointing unit timelike 4-velocity (to
// 1e-10).
template <class S>
void expect_chart_maps_and_disk(const S& st, const std::vector<Vec4>& pts, double r_min) {
  const auto scene_difference = [](Vec4 a, const Vec4& b) {
    Vec4 d = a - b;
    if constexpr (S::chart == SceneChart::polar) d[3] = std::remainder(d[3], 2 * pi);
    return d;
  };
  const Vec4 v = {0.3, -0.5, 0.7, 0.4};
  for (const Vec4& x : pts) {
    const double size = std::max(1.0, std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]));
    const Vec4 back = st.trace_from_scene(st.scene_from_trace(x));
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(back[c], x[c], 1e-9 * size) << "round trip, component " << c;
    // Polar angles vary on the scale of the distance from the axis: the
    // step shrinks with it (and the axis itself, where they are singular,
    // is left to the spacetime's own tests).
    const double rho = std::hypot(x[1], x[2]);
    if (S::chart == SceneChart::polar && rho < 1e-3) continue;
    const double h = 1e-5 * std::min(1.0, rho);
    const Vec4 fd = (1 / (2 * h)) * scene_difference(st.scene_from_trace(x + h * v), st.scene_from_trace(x - h * v));
    const Vec4 sv = st.scene_vector(x, v);
    // Truncation, and the rounding of coordinates of the event's size over 2h.
    const auto tol = [&](double f) { return 1e-6 * std::max(1.0, std::abs(f)) + 1e-15 * size / h; };
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(sv[c], fd[c], tol(fd[c])) << "scene_vector " << c;
    EXPECT_NEAR(dot(st.scene_time_gradient(x), v), fd[0], tol(fd[0]));
    if (std::hypot(x[1], x[2]) < r_min) continue;
    const Vec4 in_plane = {x[0], x[1], x[2], 0.0};
    const Vec4 u = DiskPhysics<S>::velocity(st, in_plane);
    EXPECT_NEAR(dot(mat_vec(st.metric(in_plane), u), u), -1.0, 1e-10) << "disk matter at " << x[1] << ", " << x[2];
    EXPECT_GT(u[0], 0.0);
  }
}

// The self-test every registered spacetime gets, with no line of its own
// here: on its examples(), the metric times its inverse, the analytic
// derivatives against finite differences, Hamilton's equations against the
// inverse metric and finite differences of H, and its right-hand side on
// vector lanes against the one on doubles (the ray loop runs both: the same
// arithmetic, to the last bits or a few ulps where the compiler fuses
// multiply-adds differently).
TEST(Spacetime, EveryRegisteredSpacetimePassesTheSelfTest) {
  int checked = 0;
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    const auto examples = S::examples();
    ASSERT_FALSE(examples.empty()) << S::name;
    for (const SpacetimeExample<S>& ex : examples) {
      SCOPED_TRACE(describe(ex.spacetime));
      const auto pts = test::cartesian_points(60, ex.r_min, ex.r_max);
      expect_inverse(ex.spacetime, pts);
      expect_derivatives(ex.spacetime, pts);
      expect_hamilton_equations(ex.spacetime, pts);
      expect_chart_maps_and_disk(ex.spacetime, pts, ex.r_min);
      const auto ps = test::momenta(static_cast<int>(pts.size()));
      for (std::size_t k = 0; k + lane_count <= pts.size(); k += lane_count) {
        std::array<LaneVec, 8> yl{}, dyl{};
        for (int i = 0; i < lane_count; ++i)
          for (int c = 0; c < 4; ++c) {
            yl[c][i] = pts[k + i][c];
            yl[4 + c][i] = ps[k + i][c];
          }
        ex.spacetime.rhs(yl, dyl);
        for (int i = 0; i < lane_count; ++i) {
          std::array<double, 8> y{}, dy{};
          for (int c = 0; c < 8; ++c) y[c] = yl[c][i];
          ex.spacetime.rhs(y, dy);
          for (int c = 0; c < 8; ++c) EXPECT_NEAR(dyl[c][i], dy[c], 4e-16 * std::max(1.0, std::abs(dy[c]))) << "component " << c;
        }
      }
      ++checked;
    }
  });
  EXPECT_GE(checked, 3);
}

constexpr KerrSchildSense both_senses[] = {KerrSchildSense::ingoing, KerrSchildSense::outgoing};

// Spin and charge pairs of Kerr–Newman holes (M = 1) for the checks below:
// Reissner–Nordström, charged and spinning either way, and extremal.
constexpr std::pair<double, double> charged[] = {{0.0, 0.7}, {0.5, -0.6}, {-0.6, 0.8}, {0.3, 0.2}};

TEST(Kerr, MetricTimesInverseIsIdentity) {
  for (auto sense : both_senses)
    for (double a : {0.0, 0.5, 0.9, 0.999, 1.0})
      expect_inverse(Kerr(1.0, a, sense), test::cartesian_points(200, 1.5, 60));
}

TEST(Kerr, DerivativesMatchFiniteDifferences) {
  for (auto sense : both_senses)
    for (double a : {0.0, 0.6, -0.9, 1.0})
      expect_derivatives(Kerr(1.0, a, sense), test::cartesian_points(200, 2.1, 40));
}

TEST(Kerr, HamiltonEquationsMatchFiniteDifferences) {
  for (auto sense : both_senses)
    for (double a : {0.0, 0.6, -0.9, 1.0})
      expect_hamilton_equations(Kerr(1.0, a, sense), test::cartesian_points(200, 2.1, 40));
}

TEST(Kerr, ChargedMetricInverseDerivativesAndHamiltonEquations) {
  for (auto sense : both_senses)
    for (auto [a, q] : charged) {
      const Kerr k(1.0, a, q, sense);
      expect_inverse(k, test::cartesian_points(100, 1.5, 60));
      expect_derivatives(k, test::cartesian_points(100, 2.1, 40));
      expect_hamilton_equations(k, test::cartesian_points(100, 2.1, 40));
    }
}

TEST(Kerr, ChargedBoyerLindquistIsReissnerNordstromAtZeroSpin) {
  const double M = 1.3, Q = 0.9;
  const Kerr k(M, 0.0, Q, KerrSchildSense::ingoing);
  // -g_tt = 1 / g_rr = 1 - 2M/r + Q^2/r^2.
  const double r = 4.0, th = 0.8;
  const Mat4 gb = k.bl_metric({0, r, th, 1.0});
  EXPECT_NEAR(gb[0][0], -(1 - 2 * M / r + Q * Q / (r * r)), 1e-15);
  EXPECT_NEAR(gb[1][1], 1 / (1 - 2 * M / r + Q * Q / (r * r)), 1e-14);
  EXPECT_NEAR(gb[3][3], r * r * std::sin(th) * std::sin(th), 1e-14);
}

TEST(Kerr, ZeroSpinIsSchwarzschildOrReissnerNordstromInKerrSchildForm) {
  // In ingoing Kerr–Schild form: g = eta + (2M/r - Q^2/r^2) l l, l = (1, x/r, y/r, z/r).
  const double M = 1.3;
  for (const double Q : {0.0, 0.9}) {
  const Kerr k(M, 0.0, Q, KerrSchildSense::ingoing);
  for (const auto& x : test::cartesian_points(100, 2.7, 50)) {
    const double r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    const Vec4 l = {1.0, x[1] / r, x[2] / r, x[3] / r};
    const Mat4 g = k.metric(x);
    for (int m = 0; m < 4; ++m)
      for (int n = 0; n < 4; ++n)
        EXPECT_NEAR(g[m][n], (m == n ? (m == 0 ? -1.0 : 1.0) : 0.0) + (2 * M / r - Q * Q / (r * r)) * l[m] * l[n], 1e-14)
            << "Q " << Q;
  }
  }
}

TEST(Kerr, ZeroSpinBoyerLindquistIsSchwarzschildClosedForm) {
  const Kerr k(1.0, 0.0);
  const double r = 7.0, th = 1.1;
  const Mat4 g = k.bl_metric({0, r, th, 0.3});
  EXPECT_DOUBLE_EQ(g[0][0], -(1 - 2 / r));
  EXPECT_DOUBLE_EQ(g[1][1], 1 / (1 - 2 / r));
  EXPECT_DOUBLE_EQ(g[2][2], r * r);
  EXPECT_DOUBLE_EQ(g[3][3], r * r * std::sin(th) * std::sin(th));
  EXPECT_DOUBLE_EQ(g[0][3], 0.0);
}

TEST(Kerr, KerrSchildPullsBackToBoyerLindquist) {
  // J^T g_KS J = g_BL: fixes the signs of the coordinate map (phi shift, the
  // sense of rotation) against the textbook Boyer–Lindquist metric.
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (auto sense : both_senses)
  for (auto [a, q] : {std::pair{0.0, 0.0}, {0.5, 0.0}, {-0.7, 0.0}, {0.99, 0.0}, {0.0, 0.7}, {0.5, -0.6}, {-0.6, 0.8}}) {
    const Kerr k(1.0, a, q, sense);
    for (int i = 0; i < 100; ++i) {
      const Vec4 s = {5 * u(rng), k.horizon_radius() + 0.05 + 40 * u(rng), 0.05 + 3.0 * u(rng), 6.2 * u(rng)};
      const Mat4 J = k.trace_jacobian(s);
      const Mat4 gks = k.metric(k.trace_from_scene(s));
      const Mat4 gbl = k.bl_metric(s);
      for (int m = 0; m < 4; ++m)
        for (int n = 0; n < 4; ++n) {
          double v = 0.0;
          for (int p = 0; p < 4; ++p)
            for (int q = 0; q < 4; ++q) v += J[p][m] * gks[p][q] * J[q][n];
          EXPECT_NEAR(v, gbl[m][n], 1e-9 * std::max(1.0, std::abs(gbl[m][n]))) << m << n << " a=" << a << " Q=" << q;
        }
    }
  }
}

TEST(Kerr, JacobianMatchesFiniteDifferencesOfTheMap) {
  for (auto sense : both_senses)
  for (double q : {0.0, 0.55}) {
  const Kerr k(1.0, 0.8, q, sense);
  const Vec4 s = {1.0, 6.5, 0.9, 2.0};
  const Mat4 J = k.trace_jacobian(s);
  for (int n = 0; n < 4; ++n) {
    Vec4 sp = s, sm = s;
    sp[n] += fd_step;
    sm[n] -= fd_step;
    const Vec4 xp = k.trace_from_scene(sp), xm = k.trace_from_scene(sm);
    for (int m = 0; m < 4; ++m) EXPECT_NEAR(J[m][n], (xp[m] - xm[m]) / (2 * fd_step), fd_tol);
  }
  }
}

TEST(Kerr, SceneCoordinatesRoundTrip) {
  for (auto sense : both_senses) {
  const Kerr k(1.0, 0.9, sense);
  for (double th : {0.0, 1e-7, 0.4, 1.5707963267948966, 2.9, 3.141592653589793})
    for (double ph : {0.0, 1.0, 4.0}) {
      const Vec4 s = {3.0, 7.5, th, ph};
      const Vec4 back = k.scene_from_trace(k.trace_from_scene(s));
      EXPECT_NEAR(back[0], s[0], 1e-12);
      EXPECT_NEAR(back[1], s[1], 1e-12);
      EXPECT_NEAR(back[2], s[2], 1e-7);
      if (std::sin(th) > 1e-3) {
        EXPECT_NEAR(back[3], s[3], 1e-12);
      }
    }
  }
}

TEST(Kerr, SceneTimeGradientMatchesFiniteDifferences) {
  for (auto sense : both_senses)
  for (double q : {0.0, 0.65}) {
  const Kerr k(1.0, 0.7, q, sense);
  for (const auto& x : test::cartesian_points(50, 3, 30)) {
    const Vec4 g = k.scene_time_gradient(x);
    for (int m = 0; m < 4; ++m) {
      Vec4 xp = x, xm = x;
      xp[m] += fd_step;
      xm[m] -= fd_step;
      EXPECT_NEAR(g[m], (k.scene_from_trace(xp)[0] - k.scene_from_trace(xm)[0]) / (2 * fd_step), 1e-6);
    }
  }
  }
}

TEST(Kerr, ZeroMassIsFlat) {
  const Kerr k(0.0, 0.0);
  for (const auto& x : test::cartesian_points(20, 0.5, 10)) {
    const Mat4 g = k.metric(x);
    for (int m = 0; m < 4; ++m)
      for (int n = 0; n < 4; ++n) EXPECT_EQ(g[m][n], m == n ? (m == 0 ? -1.0 : 1.0) : 0.0);
    EXPECT_FALSE(k.captured(x));
  }
}

TEST(Kerr, RejectsUnphysicalParameters) {
  EXPECT_THROW(Kerr(-1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(Kerr(1.0, 1.01), std::invalid_argument);
  EXPECT_THROW(Kerr(1.0, -1.01), std::invalid_argument);
  EXPECT_THROW(Kerr(0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(Kerr(std::nan(""), 0.0), std::invalid_argument);
  // a^2 + Q^2 > M^2: no horizon.
  EXPECT_THROW(Kerr(1.0, 0.0, 1.01), std::invalid_argument);
  EXPECT_THROW(Kerr(1.0, 0.6, -0.81), std::invalid_argument);
  EXPECT_THROW(Kerr(0.0, 0.0, 0.1), std::invalid_argument);
  EXPECT_THROW(Kerr(1.0, 0.0, std::nan("")), std::invalid_argument);
  EXPECT_NO_THROW(Kerr(1.0, 0.6, 0.8));
  try {
    Kerr(1.0, 0.9, 0.5);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a^2 + Q^2 <= M^2"), std::string::npos) << e.what();
  }
}

TEST(Kerr, ChartsDescribeTheSameSpacetime) {
  // Both charts pulled back to Boyer–Lindquist give the same metric (checked
  // above); here: the same scene point maps to different charts but the same
  // scene point back, and the outgoing chart is the time-reversed ingoing one.
  const Kerr in(1.0, 0.9, KerrSchildSense::ingoing), out(1.0, 0.9, KerrSchildSense::outgoing);
  const Vec4 s = {2.0, 5.0, 1.0, 0.5};
  const Vec4 xi = in.trace_from_scene(s), xo = out.trace_from_scene(s);
  EXPECT_NEAR(xi[0] - s[0], -(xo[0] - s[0]), 1e-12);
  const Vec4 bo = out.scene_from_trace(xo);
  for (int m = 0; m < 4; ++m) EXPECT_NEAR(bo[m], s[m], 1e-12);
}

TEST(Kerr, HorizonAndCaptureRadii) {
  const Kerr k(1.0, 0.9);
  EXPECT_NEAR(k.horizon_radius(), 1.0 + std::sqrt(1 - 0.81), 1e-15);
  // Prograde photon orbit for a = 0.9 is r = 1.5578 (Bardeen et al. 1972).
  EXPECT_GT(k.capture_radius(), k.horizon_radius());
  EXPECT_LT(k.capture_radius(), 1.5578);
  EXPECT_NEAR(Kerr(1.0, 0.0).capture_radius(), 2.5, 1e-12);
  // Kerr–Newman: r_+- = M +- sqrt(M^2 - a^2 - Q^2), the capture radius
  // between the horizon and the prograde photon orbit.
  for (auto [a, q] : charged) {
    const Kerr c(1.0, a, q);
    const double root = std::sqrt(std::max(0.0, 1 - a * a - q * q));  // 0.6^2 + 0.8^2 rounds above 1
    EXPECT_NEAR(c.horizon_radius(), 1 + root, 1e-15);
    EXPECT_NEAR(c.inner_horizon_radius(), 1 - root, 1e-15);
    EXPECT_GT(c.capture_radius(), c.horizon_radius());
    // Extremal: the prograde photon orbit is on the horizon; rays are
    // captured just outside it.
    EXPECT_LE(c.capture_radius(), std::max(c.photon_orbit_radius(true), 1.001 * c.horizon_radius()));
  }
}

TEST(Kerr, ChargeIsLeftOutOfTheDescriptionOfAnUnchargedHole) {
  // Frames of Kerr shots name their spacetime in their files: an uncharged
  // hole is described as before the charge existed.
  EXPECT_EQ(describe(Spacetime(Kerr(1.0, 0.5))), "kerr(mass=1, spin=0.5)");
  EXPECT_EQ(spacetime_json(Spacetime(Kerr(1.0, 0.5))), R"({"kind": "kerr", "mass": 1, "spin": 0.5})");
  EXPECT_EQ(describe(Spacetime(Kerr(1.0, 0.5, 0.25))), "kerr(mass=1, spin=0.5, charge=0.25)");
  EXPECT_EQ(spacetime_json(Spacetime(Kerr(1.0, 0.5, 0.25))),
            R"({"kind": "kerr", "mass": 1, "spin": 0.5, "charge": 0.25})");
}

TEST(Dihole, MetricTimesInverseIsIdentity) {
  expect_inverse(Dihole(0.4, 0.4, 1.0), test::cartesian_points(200, 0.2, 60));
}

TEST(Dihole, DerivativesMatchFiniteDifferences) {
  expect_derivatives(Dihole(0.4, 0.7, 1.0), test::cartesian_points(200, 0.3, 30));
}

TEST(Dihole, HamiltonEquationsMatchFiniteDifferences) {
  expect_hamilton_equations(Dihole(0.4, 0.25, 1.5), test::cartesian_points(200, 0.3, 30));
}

TEST(Dihole, ClosedFormAtAPoint) {
  const Dihole d(0.4, 0.4, 1.0);
  // At (3, 0, 0): |x - x_i| = sqrt(10), U = 1 + 0.8 / sqrt(10).
  const double U = 1 + 0.8 / std::sqrt(10.0);
  const Mat4 g = d.metric({0, 3, 0, 0});
  EXPECT_NEAR(g[0][0], -1 / (U * U), 1e-15);
  EXPECT_NEAR(g[1][1], U * U, 1e-15);
  EXPECT_FALSE(d.captured({0, 3, 0, 0}));
  EXPECT_TRUE(d.captured({0, 0, 0, 1.0 + 0.01}));
}

TEST(Dihole, ZeroMassesAreFlat) {
  const Dihole d(0.0, 0.0, 1.0);
  const Mat4 g = d.metric({0, 0.1, 0.2, 1.0});
  EXPECT_EQ(g[0][0], -1.0);
  EXPECT_EQ(g[3][3], 1.0);
  EXPECT_FALSE(d.captured({0, 0, 0, 1.0}));
}

TEST(Dihole, RejectsUnphysicalParameters) {
  EXPECT_THROW(Dihole(-0.1, 0.4, 1.0), std::invalid_argument);
  EXPECT_THROW(Dihole(0.1, 0.4, 0.0), std::invalid_argument);
}

TEST(Minkowski, HamiltonEquations) {
  expect_inverse(Minkowski{}, test::cartesian_points(10, 1, 10));
  expect_hamilton_equations(Minkowski{}, test::cartesian_points(10, 1, 10));
}

// A toy spacetime (flat, written in the test) that writes only its metric,
// rhs, ends and far field: hamiltonian_rhs, the far-end rule, the capture
// rule and the disk's flux come from the bases it names
// (spacetime/model.hpp), and it satisfies the concept a registered
// spacetime must.
class ToyFlat : public CartesianScene,
                public HamiltonianFromRhs<ToyFlat>,
                public CartesianInfinity,
                public NoHorizon {
 public:
  static constexpr std::string_view name = "toy_flat";
  static constexpr SceneChart chart = SceneChart::cartesian;
  static constexpr bool stationary = true;
  static constexpr std::array ends = {SpacetimeEnd{"infinity", EndKind::infinity}};
  struct Params {
    static constexpr auto fields = std::tuple{};
  };
  ToyFlat() = default;
  explicit ToyFlat(const Params&) {}
  Params params() const { return {}; }
  ToyFlat for_tracing(TimeDirection) const { return *this; }
  static std::vector<SpacetimeExample<ToyFlat>> examples() { return {{ToyFlat{}, 0.5, 40.0}}; }
  double photon_reach() const { return 0.0; }
  double far_field_radius() const { return 0.0; }
  Vec3 escape_direction(const Vec4&, const Vec3& d) const { return d; }
  // Straight lines, with a twist the test can see: dx^1 = 2 p_1.
  template <class T>
  void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    dy = {-y[4], 2.0 * y[5], y[6], y[7], T{}, T{}, T{}, T{}};
  }
  double asymptotic_mass() const { return 0.0; }
  Mat4 metric(const Vec4&) const { return {{{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}; }
  Mat4 inverse_metric(const Vec4& x) const { return metric(x); }
  Mat4Derivs metric_derivatives(const Vec4&) const { return {}; }
};

TEST(Spacetime, ANewSpacetimeNeedNotWriteTheAdapterNorTheNoHorizonDefaultsNorAnyDiskCode) {
  static_assert(SpacetimeModel<ToyFlat>);
  const ToyFlat st;
  Vec4 dx, dp;
  st.hamiltonian_rhs({0, 1, 2, 3}, {-1, 0.5, 0.25, 0.125}, dx, dp);
  EXPECT_EQ(dx, (Vec4{1, 1.0, 0.25, 0.125}));  // its own rhs, x and p apart
  EXPECT_EQ(dp, (Vec4{0, 0, 0, 0}));
  EXPECT_FALSE(st.captured({0, 0, 0, 0}));
  EXPECT_GT(st.capture_margin({0, 0, 0, 0}), 0.0);
  EXPECT_FALSE(st.inside_horizon({0, 0, 0, 0}));
  EXPECT_TRUE(st.why_no_observer({0, 0, 0, 0}).empty());
  // No disk code: a disk in it is matter at rest that cannot glow.
  EXPECT_FALSE(DiskPhysics<ToyFlat>::flux(st));
  EXPECT_EQ(DiskPhysics<ToyFlat>::velocity(st, {0, 5, 0, 0}), (Vec4{1, 0, 0, 0}));
}

// The shared adapter is each registered spacetime's rhs<double>, to the bit.
TEST(Spacetime, TheSharedHamiltonianAdapterIsEachSpacetimesRhs) {
  const Vec4 x = {0.5, 7.0, -3.0, 2.5}, p = {-1.0, 0.3, -0.6, 0.2};
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    for (const auto& ex : S::examples()) {
      std::array<double, 8> d;
      ex.spacetime.template rhs<double>({x[0], x[1], x[2], x[3], p[0], p[1], p[2], p[3]}, d);
      Vec4 dx, dp;
      ex.spacetime.hamiltonian_rhs(x, p, dx, dp);
      EXPECT_EQ(dx, (Vec4{d[0], d[1], d[2], d[3]})) << S::name;
      EXPECT_EQ(dp, (Vec4{d[4], d[5], d[6], d[7]})) << S::name;
    }
  });
}

}  // namespace
}  // namespace lc
