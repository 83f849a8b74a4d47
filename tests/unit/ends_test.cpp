// The ends of a ray as a seam (spacetime/ends.hpp): the one infinity of a
// Cartesian-like chart, the registered spacetimes' lists, and a spacetime
// written here with two far ends — the Ellis wormhole — traced through the
// renderer's own trace and shade stages: rays through the throat reach the
// other infinity and see its sky, the rest see this side's, the throat's
// disc has the angular radius known in closed form, and an observer beyond
// the throat is accepted and sees the two skies the other way round.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "camera/pinhole_params.hpp"
#include "core/constants.hpp"
#include "eye/tetrad.hpp"
#include "render/trace_templates.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {
namespace {

// The Ellis wormhole of throat radius b, ds^2 = -dt^2 + dl^2 + (l^2 + b^2) dOmega^2,
// in the isotropic Cartesian chart: l = (rho - b^2/rho) / 2, so
// ds^2 = -dt^2 + Omega^2 |dx|^2 with Omega = (1 + b^2/rho^2) / 2.  The
// throat is the sphere rho = b; rho -> infinity is this side's infinity
// (end 0), rho -> 0 the other side's (end 1), and the inversion
// x -> b^2 x / rho^2 is an isometry that swaps them (Ellis 1973; Morris and
// Thorne 1988, the "drainhole" of their example).  A ray's radial measure
// for the far-end rule is l, the proper distance from the throat.
class Wormhole : public CartesianScene, public HamiltonianFromRhs<Wormhole>, public NoHorizon {
 public:
  static constexpr std::string_view name = "toy_wormhole";
  static constexpr SceneChart chart = SceneChart::cartesian;
  static constexpr bool stationary = true;
  static constexpr std::array ends = {SpacetimeEnd{"infinity", EndKind::infinity},
                                      SpacetimeEnd{"infinity beyond the throat", EndKind::infinity}};
  struct Params {
    static constexpr auto fields = std::tuple{};
  };
  explicit Wormhole(double b = 1.0) : b2_(b * b) {}
  explicit Wormhole(const Params&) {}
  Params params() const { return {}; }
  Wormhole for_tracing(TimeDirection) const { return *this; }
  static std::vector<SpacetimeExample<Wormhole>> examples() { return {{Wormhole{1.0}, 0.3, 40.0}}; }
  double photon_reach() const { return std::sqrt(b2_); }  // the throat is its photon sphere
  double far_field_radius() const { return std::numeric_limits<double>::infinity(); }
  double asymptotic_mass() const { return 0.0; }

  // l, signed: > 0 on this side of the throat.
  double proper_radius(double rho2) const { return 0.5 * (std::sqrt(rho2) - b2_ / std::sqrt(rho2)); }

  // End 0 beyond |l| = escape radius with l growing; end 1 likewise with l
  // < 0, where l grows in size as rho shrinks.
  template <class Y, class D>
  Flight flight(const Y& y, const D& dy, const FlightRadii& radii) const {
    const double l = proper_radius(y(1) * y(1) + y(2) * y(2) + y(3) * y(3));
    const double l2 = l * l;
    if (!(l2 > radii.free2) && !(l2 > radii.escape2)) return {};
    const double x_dx = y(1) * dy(1) + y(2) * dy(2) + y(3) * dy(3);
    const bool away = l > 0.0 ? x_dx > 0.0 : x_dx < 0.0;
    return {l2 > radii.free2 && away, l2 > radii.escape2 && away, static_cast<std::uint8_t>(l > 0.0 ? 0 : 1)};
  }
  // Both infinities are asymptotically flat: their sky's source at rest has
  // lapse 1.
  double sky_source_lapse(std::size_t) const { return 1.0; }
  // Beyond the throat the directions of the other side's sky are those of
  // the inverted chart, where the ray moves outwards: d reflected in the
  // plane normal to x (the inversion's differential, up to scale).
  Vec3 escape_direction(const Vec4& x, const Vec3& d) const {
    const double rho2 = x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    if (rho2 >= b2_) return d;
    const double xd = (x[1] * d[0] + x[2] * d[1] + x[3] * d[2]) / rho2;
    return {d[0] - 2 * xd * x[1], d[1] - 2 * xd * x[2], d[2] - 2 * xd * x[3]};
  }
  // H = (-p_t^2 + |p|^2 / Omega^2) / 2: dx = p / Omega^2,
  // dp = |p|^2 Omega^-3 grad Omega with grad Omega = -b^2 x / rho^4.
  template <class T>
  void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    const T rho2 = y[1] * y[1] + y[2] * y[2] + y[3] * y[3];
    const T om = 0.5 * (1.0 + b2_ / rho2);
    const T iom2 = 1.0 / (om * om);
    const T p2 = y[5] * y[5] + y[6] * y[6] + y[7] * y[7];
    const T k = -p2 * iom2 / om * b2_ / (rho2 * rho2);
    dy = {-y[4], iom2 * y[5], iom2 * y[6], iom2 * y[7], T{}, k * y[1], k * y[2], k * y[3]};
  }
  Mat4 metric(const Vec4& x) const {
    const double o2 = omega(x) * omega(x);
    return {{{-1, 0, 0, 0}, {0, o2, 0, 0}, {0, 0, o2, 0}, {0, 0, 0, o2}}};
  }
  Mat4 inverse_metric(const Vec4& x) const {
    const double i2 = 1.0 / (omega(x) * omega(x));
    return {{{-1, 0, 0, 0}, {0, i2, 0, 0}, {0, 0, i2, 0}, {0, 0, 0, i2}}};
  }
  Mat4Derivs metric_derivatives(const Vec4& x) const {
    const double rho2 = x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    Mat4Derivs d{};
    for (int k = 1; k < 4; ++k) {
      const double dg = 2.0 * omega(x) * (-b2_ * x[k] / (rho2 * rho2));
      for (int i = 1; i < 4; ++i) d[k][i][i] = dg;
    }
    return d;
  }

 private:
  double omega(const Vec4& x) const { return 0.5 * (1.0 + b2_ / (x[1] * x[1] + x[2] * x[2] + x[3] * x[3])); }
  double b2_ = 1.0;
};

static_assert(SpacetimeModel<Wormhole>, "a two-ended spacetime written outside the engine satisfies the concept");
static_assert(end_index<Wormhole>(EndKind::horizon) == Wormhole::ends.size());  // none: no ray is captured

// The wormhole itself first, so what follows tests the ends and not a
// wrong metric: Hamilton's equations against central differences of H
// (step 1e-5: truncation ~1e-10; bound 1e-7 relative), on both sides of
// the throat.
TEST(Ends, TheToyWormholeIsItsOwnHamiltonian) {
  const Wormhole st(1.0);
  const auto H = [&](const Vec4& x, const Vec4& p) { return 0.5 * contract(st.inverse_metric(x), p, p); };
  for (const Vec4& x : {Vec4{0, 3.0, -1.0, 2.0}, Vec4{0, 0.2, 0.3, -0.1}, Vec4{0, 0.9, 0.1, 0.2}}) {
    const Vec4 p = {-1.0, 0.3, -0.6, 0.2};
    Vec4 dx, dp;
    st.hamiltonian_rhs(x, p, dx, dp);
    const Vec4 dx_ref = mat_vec(st.inverse_metric(x), p);
    const Mat4Derivs dg = st.metric_derivatives(x);
    for (int m = 0; m < 4; ++m) {
      EXPECT_NEAR(dx[m], dx_ref[m], 1e-12 * std::max(1.0, std::abs(dx_ref[m])));
      Vec4 xp = x, xm = x;
      xp[m] += 1e-5;
      xm[m] -= 1e-5;
      const double dH = (H(xp, p) - H(xm, p)) / 2e-5;
      EXPECT_NEAR(dp[m], -dH, 1e-7 * std::max(1.0, std::abs(dH))) << "component " << m;
      const double dg11 = (st.metric(xp)[1][1] - st.metric(xm)[1][1]) / 2e-5;
      EXPECT_NEAR(dg[m][1][1], dg11, 1e-7 * std::max(1.0, std::abs(dg11)));
    }
  }
}

TEST(Ends, CartesianInfinityIsReachedBeyondTheEscapeRadiusMovingOut) {
  const FlightRadii radii{10.0 * 10.0, 20.0 * 20.0};
  const std::array<double, 8> near = {0, 5, 0, 0}, free = {0, 15, 0, 0}, far = {0, 0, 0, 25};
  const std::array<double, 8> out_x = {0, 1, 0, 0}, in_x = {0, -1, 0, 0}, out_z = {0, 0, 0, 1};
  const auto at = [&](const std::array<double, 8>& y, const std::array<double, 8>& dy) {
    return CartesianInfinity::flight(StateComponents{&y}, StateComponents{&dy}, radii);
  };
  EXPECT_FALSE(at(near, out_x).free);
  EXPECT_FALSE(at(near, out_x).escaped);
  EXPECT_TRUE(at(free, out_x).free);
  EXPECT_FALSE(at(free, out_x).escaped);
  EXPECT_FALSE(at(free, in_x).free);
  EXPECT_TRUE(at(far, out_z).escaped);
  EXPECT_EQ(at(far, out_z).end, 0);
  EXPECT_FALSE(at(far, in_x).escaped);  // moving in (x . dx = 0 here: not out)
}

// Every registered spacetime names its ends: the far end where the
// scene's sky is first (infinity, or a cosmological horizon where there is
// no infinity to reach), each end's name its kind's, then its horizons,
// whose index the hit records of captured rays carry.
TEST(Ends, RegisteredSpacetimesListTheirSkysEndFirst) {
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    EXPECT_TRUE(is_far(S::ends[0].kind)) << S::name;
    for (const SpacetimeEnd& e : S::ends)
      if (e.kind != EndKind::infinity) EXPECT_EQ(e.name, to_string(e.kind)) << S::name;
  });
  EXPECT_EQ(end_index<Kerr>(EndKind::horizon), 1u);
  EXPECT_EQ(end_index<Dihole>(EndKind::horizon), 1u);
  EXPECT_EQ(end_index<Kottler>(EndKind::horizon), 1u);
  EXPECT_EQ(end_index<Kottler>(EndKind::cosmological_horizon), 0u);
  EXPECT_EQ(end_index<Minkowski>(EndKind::horizon), Minkowski::ends.size());
  EXPECT_EQ(to_string(EndKind::cosmological_horizon), "cosmological horizon");
}

// A frame in the wormhole seen by a static observer at isotropic radius
// rho (on the +x axis), this side's sky uniformly `here`, the other side's
// `there`.
SceneIn<Wormhole> wormhole_scene(double rho, ShotResources& res) {
  const Wormhole st(1.0);
  const auto uniform = [&](float c) {
    CheckerSky::Params p;
    p.colors = Palette{{c, c, c}, {c, c, c}};
    return Sky(SkySpec{p}, res);
  };
  RayOptions rays;
  rays.escape = EscapeRule::fixed;
  rays.escape_radius = 60.0;  // in l: the rest of the bending, ~b^2/l^2, is below 3e-4
  rays.free_radius = 0.0;
  SceneIn<Wormhole> sc{st, {}, Camera(PinholeParams{}, 8, 8), uniform(0.25f), {{1, uniform(0.75f)}}, std::make_shared<ObjectSet>(), rays};
  sc.eye.event = sc.eye.scene_event = {0.0, rho, 0.0, 0.0};
  sc.eye.metric = st.metric(sc.eye.event);
  sc.eye.frame = static_cartesian_tetrad(st, sc.eye.event);
  return sc;
}

// The directions at angle alpha from the eye's -x leg (towards the origin),
// in the x-y and x-z planes.
std::vector<Vec3> at_angle(double alpha) {
  return {{-std::cos(alpha), std::sin(alpha), 0.0}, {-std::cos(alpha), 0.0, -std::sin(alpha)}};
}

std::vector<RaySample> traced(const SceneIn<Wormhole>& sc, const std::vector<Vec3>& dirs) {
  std::vector<RaySample> out(dirs.size());
  trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(out));
  return out;
}

// From l0 = 10 b a ray at angle alpha from the inward radial direction has
// impact parameter h = sqrt(l0^2 + b^2) sin(alpha); it passes the throat
// iff h < b (the radial equation (dl/dlambda)^2 = E^2 - L^2 / (l^2 + b^2)
// has no turning point), so the other sky fills a disc of angular radius
// arcsin(b / sqrt(l0^2 + b^2)).  Rays at 0.98 and 1.02 of that angle fall on
// either side: the ray loop's tolerance moves the edge by far less.
TEST(Ends, RaysThroughTheThroatSeeTheOtherSky) {
  ShotResources res;
  const double l0 = 10.0, rho0 = l0 + std::sqrt(l0 * l0 + 1.0);  // l = (rho - 1/rho)/2
  const SceneIn<Wormhole> sc = wormhole_scene(rho0, res);
  const double edge = std::asin(1.0 / std::sqrt(l0 * l0 + 1.0));
  for (double f : {0.0, 0.5, 0.98}) {
    for (const RaySample& s : traced(sc, at_angle(f * edge))) {
      SCOPED_TRACE(f);
      EXPECT_EQ(s.hit.kind, HitKind::sky);
      EXPECT_EQ(s.hit.reason, StopReason::escaped);
      EXPECT_EQ(s.hit.spacetime_end, 1);
      EXPECT_NEAR(s.color[0], 0.75f, 1e-6f);
      EXPECT_LT(s.sky.theta, 0.0) << "no point stars across the throat";
    }
  }
  for (double f : {1.02, 1.5, 3.0}) {
    for (const RaySample& s : traced(sc, at_angle(f * edge))) {
      SCOPED_TRACE(f);
      EXPECT_EQ(s.hit.spacetime_end, 0);
      EXPECT_NEAR(s.color[0], 0.25f, 1e-6f);
      EXPECT_GE(s.sky.theta, 0.0);
    }
  }
  // Straight in along -x: through the throat, out along +x of the other
  // side's chart (the inversion keeps the axis), to the escape radius's
  // remaining bending (none, on the axis) and the ray tolerance.
  const RaySample radial = traced(sc, {{-1.0, 0.0, 0.0}})[0];
  EXPECT_EQ(radial.hit.spacetime_end, 1);
  EXPECT_NEAR(radial.hit.sky_theta, pi / 2, 1e-6);
  EXPECT_NEAR(std::remainder(radial.hit.sky_phi, two_pi), 0.0, 1e-6);
  // Away from the throat: this side's sky straight ahead.
  const RaySample away = traced(sc, {{1.0, 0.0, 0.0}})[0];
  EXPECT_EQ(away.hit.spacetime_end, 0);
  EXPECT_NEAR(away.hit.sky_theta, pi / 2, 1e-6);
}

// Beyond the throat (rho = 0.2 b, l = -2.4 b) an observer may stand: it
// sees the first end's sky through the throat (+x, towards larger rho) and
// the other end's sky behind it.
TEST(Ends, AnObserverBeyondTheThroatSeesTheSkiesTheOtherWayRound) {
  ShotResources res;
  EXPECT_TRUE(Wormhole(1.0).why_no_observer({0.0, 0.2, 0.0, 0.0}).empty());
  const SceneIn<Wormhole> sc = wormhole_scene(0.2, res);
  const std::vector<RaySample> s = traced(sc, {{1.0, 0.0, 0.0}, {-1.0, 0.0, 0.0}});
  EXPECT_EQ(s[0].hit.spacetime_end, 0);
  EXPECT_NEAR(s[0].color[0], 0.25f, 1e-6f);
  EXPECT_EQ(s[1].hit.spacetime_end, 1);
  EXPECT_NEAR(s[1].color[0], 0.75f, 1e-6f);
}

// A scene's one sky serves every far end that has none of its own.
TEST(Ends, AnEndWithoutASkyOfItsOwnSeesTheScenesSky) {
  ShotResources res;
  SceneIn<Wormhole> sc = wormhole_scene(10.0 + std::sqrt(101.0), res);
  sc.end_skies.clear();
  const RaySample s = traced(sc, {{-1.0, 0.0, 0.0}})[0];
  EXPECT_EQ(s.hit.spacetime_end, 1);
  EXPECT_NEAR(s.color[0], 0.25f, 1e-6f);
}

}  // namespace
}  // namespace lc
