#pragma once
// What every spacetime is: the C++ concept a class must satisfy to be
// registered (spacetime/spacetime.hpp), so that a spacetime that forgets
// one of these is a compile error rather than a quietly wrong picture.
// No virtual calls: the ray loop is instantiated per spacetime and the
// metric inlines into the integrator.
//
//   name, chart, stationary   static: its Lua constructor lc.<name>{...}, its
//                             scene coordinates (spacetime/chart.hpp), whether
//                             the metric is independent of t (frames that
//                             differ only in time may then share rays)
//   Params                    its parameters as a plain struct with declared
//                             fields (core/fields.hpp): the Lua reader, the
//                             description, the JSON and the docs come from them;
//                             S(Params) validates (std::invalid_argument),
//                             params() gives them back
//   rhs<T>(y, dy)             Hamilton's equations in the trace chart on
//                             y = (x^mu, p_mu), T double or lanes
//   hamiltonian_rhs(x, p, dx, dp)   the same for one ray, x and p apart
//                             (HamiltonianFromRhs below writes it)
//   metric, inverse_metric, metric_derivatives   in the trace chart
//   ends                      static: its ends (spacetime/ends.hpp) — infinity,
//                             a second infinity, a cosmological horizon, its
//                             horizons; ends[0] is where the scene's sky is
//   flight(y, dy, radii)      which far end a ray moving on has reached, in
//                             its own chart (CartesianInfinity below: the one
//                             infinity of a Cartesian-like chart)
//   sky_source_lapse(end)     √(-g_tt) of the source at rest, in the trace
//                             chart, that a far end's sky light is measured
//                             against (its hit.g is this over p_t): 1 where
//                             g_tt -> -1 at infinity (CartesianInfinity);
//                             Kottler's, with no such region, its own
//   flight_reach(lo, hi)      the largest value of flight()'s radial
//                             measure over the trace chart's shell lo <= |x|
//                             <= hi (an object's reach, objects/objects.hpp):
//                             hi for CartesianInfinity; a wormhole's |l|
//                             grows without bound towards x = 0
//   captured(x), capture_margin(x), inside_horizon(x)   where rays are captured
//                             by a horizon (none are: NoHorizon below)
//   why_no_observer(x)        why no observer may stand at the trace event x,
//                             empty where one may (ObserversOutsideHorizons
//                             below: anywhere outside a horizon)
//   asymptotic_mass()         the mass seen from far away
//   photon_reach()            a radius, in flight()'s measure, within which
//                             all of its photon orbits lie (rays beyond it,
//                             moving out, never turn back)
//   far_field_radius()        where (flight()'s measure) its far field is
//                             known well enough
//                             (far_field_bending) for the escape direction
//                             to be computed instead of integrated; infinity
//                             where it is not
//   escape_direction(x, d)    the direction at infinity of a ray leaving x
//                             along unit spatial direction d (the bending
//                             still to come)
//   trace_from_scene, scene_from_trace, scene_vector, scene_time_gradient,
//   polar_basis               scene <-> trace coordinates
//   for_tracing(direction)    itself in the chart regular where curves traced
//                             that way go
//   (the trace chart's t must be a static observer's time up to the lapse
//   sky_source_lapse gives, so that a ray's p_t is its energy there: the
//   sky's hit.g reads it)
//   examples()                parameter sets with the radii between which
//                             the generic self-test may sample events
//   signed_radius             optional, static: true where the polar scene
//                             chart's r is signed (a wormhole's l), so
//                             positions may have r <= 0
//   other_names               optional, static: names a user may try for
//                             special cases it covers, each with how it is
//                             written (lc.kerr_newman: lc.kerr{..., charge});
//                             lc's unknown-name error says so
//
// The requirements come in three parts, each a concept of its own so that
// the compiler's note names the part a class misses: what it is
// (SpacetimeMetric: the metric and Hamilton's equations), where rays end
// (SpacetimeEnds: its far ends, horizons and capture, the far field) and
// its charts (SpacetimeCharts: scene <-> trace coordinates).  How its
// equatorial matter moves and a thin disk's physics are no part of it:
// traits beside it (spacetime/equatorial_flow.hpp) and beside the disk
// (objects/disk_physics.hpp), so a spacetime without them writes no orbit
// or disk code.
//
// What most spacetimes would write alike comes from bases they name
// (below), each a choice the class states rather than a default it falls
// into: HamiltonianFromRhs<S> (hamiltonian_rhs from rhs<double>),
// CartesianInfinity (spacetime/ends.hpp: one infinity, by the trace chart's
// Cartesian radius), NoHorizon (rays are never captured, observers stand
// anywhere) and ObserversOutsideHorizons<S>.

#include <algorithm>
#include <array>
#include <concepts>
#include <optional>
#include <string_view>
#include <vector>

#include "core/fields.hpp"
#include "core/lanes.hpp"
#include "core/tensor.hpp"
#include "spacetime/chart.hpp"
#include "spacetime/ends.hpp"

namespace lc {

// A name a user may try for a special case of a spacetime (S::other_names)
// and how the case is written in a shot.
struct OtherName {
  std::string_view name, written;
};

// A spacetime and where events may be sampled in it (trace coordinates,
// Cartesian radius in [r_min, r_max]), for the generic self-test.
template <class S>
struct SpacetimeExample {
  S spacetime;
  double r_min, r_max;
};

// What it is: its name, scene chart, whether it is stationary, its
// parameters, the metric and Hamilton's equations in the trace chart, the
// mass seen from far away, and the examples the self-test samples.
template <class S>
concept SpacetimeMetric = requires(const S& s, const typename S::Params& params, const Vec4& x,
                                   const std::array<double, 8>& y, std::array<double, 8>& dy,
                                   const std::array<LaneVec, 8>& yl, std::array<LaneVec, 8>& dyl, Vec4& out) {
  requires std::same_as<std::remove_cv_t<decltype(S::name)>, std::string_view>;
  requires std::same_as<std::remove_cv_t<decltype(S::chart)>, SceneChart>;
  requires std::same_as<std::remove_cv_t<decltype(S::stationary)>, bool>;
  requires HasFields<typename S::Params>;
  S(params);
  { s.params() } -> std::same_as<typename S::Params>;
  s.rhs(y, dy);
  s.rhs(yl, dyl);
  s.hamiltonian_rhs(x, x, out, out);
  { s.metric(x) } -> std::same_as<Mat4>;
  { s.inverse_metric(x) } -> std::same_as<Mat4>;
  { s.metric_derivatives(x) } -> std::same_as<Mat4Derivs>;
  { s.asymptotic_mass() } -> std::same_as<double>;
  { S::examples() } -> std::same_as<std::vector<SpacetimeExample<S>>>;
};

// Where rays end: its ends, which one a ray moving on has reached, capture
// by its horizons, where observers may stand, and its far field.
template <class S>
concept SpacetimeEnds = requires(const S& s, const Vec4& x, const Vec3& d, const StateComponents& c,
                                 const FlightRadii& radii) {
  requires ends_are_well_formed<S>();
  { s.captured(x) } -> std::same_as<bool>;
  { s.capture_margin(x) } -> std::same_as<double>;
  { s.inside_horizon(x) } -> std::same_as<bool>;
  { s.flight(c, c, radii) } -> std::same_as<Flight>;
  { s.sky_source_lapse(std::size_t{}) } -> std::same_as<double>;
  { s.flight_reach(1.0, 2.0) } -> std::same_as<double>;
  { s.why_no_observer(x) } -> std::same_as<std::string_view>;
  { s.photon_reach() } -> std::same_as<double>;
  { s.far_field_radius() } -> std::same_as<double>;
  { s.escape_direction(x, d) } -> std::same_as<Vec3>;
};

// Its charts: scene <-> trace coordinates, and itself in the chart regular
// where curves traced one way in time go.
template <class S>
concept SpacetimeCharts = requires(const S& s, const Vec4& x) {
  { s.trace_from_scene(x) } -> std::same_as<Vec4>;
  { s.scene_from_trace(x) } -> std::same_as<Vec4>;
  { s.scene_vector(x, x) } -> std::same_as<Vec4>;
  { s.scene_time_gradient(x) } -> std::same_as<Vec4>;
  { s.polar_basis(x) } -> std::same_as<std::array<Vec4, 4>>;
  { s.for_tracing(TimeDirection::past) } -> std::same_as<S>;
};

template <class S>
concept SpacetimeModel = SpacetimeMetric<S> && SpacetimeEnds<S> && SpacetimeCharts<S>;

// hamiltonian_rhs for the CRTP class S from its rhs<double>: the state
// (x, p) packed as rhs takes it, the derivative unpacked.  Inline and
// templated on S, so S's rhs inlines into it as it would into a copy
// written in S (the dihole's is always_inline: docs/performance.md,
// change 32).
template <class S>
struct HamiltonianFromRhs {
  void hamiltonian_rhs(const Vec4& x, const Vec4& p, Vec4& dx, Vec4& dp) const {
    std::array<double, 8> d;
    static_cast<const S&>(*this).template rhs<double>({x[0], x[1], x[2], x[3], p[0], p[1], p[2], p[3]}, d);
    dx = {d[0], d[1], d[2], d[3]};
    dp = {d[4], d[5], d[6], d[7]};
  }
};

// The capture rule of a spacetime without a horizon: no ray is captured,
// the margin never reaches 0, an observer may stand anywhere.
struct NoHorizon {
  bool captured(const Vec4&) const { return false; }
  double capture_margin(const Vec4&) const { return 1.0; }
  bool inside_horizon(const Vec4&) const { return false; }
  std::string_view why_no_observer(const Vec4&) const { return {}; }
};

// Where observers of the CRTP class S may stand: anywhere outside its
// horizons (S::inside_horizon).
template <class S>
struct ObserversOutsideHorizons {
  std::string_view why_no_observer(const Vec4& x) const {
    return static_cast<const S&>(*this).inside_horizon(x) ? "inside a horizon" : std::string_view{};
  }
};

// The direction at infinity of a ray leaving the Kerr–Schild-like point x
// along unit direction d, in a far field of mass M to first order:
// deflected by (2M/r) tan(psi/2) towards the centre (psi: the angle between
// position and direction).  Without it the sky would sit ~2M/R radians off
// at the escape radius R.
inline Vec3 first_order_escape_direction(const Vec4& x, Vec3 d, double M) {
  if (!(M > 0.0)) return d;
  const double rho = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
  const Vec3 rh = {x[1] / rho, x[2] / rho, x[3] / rho};
  const double c = std::clamp(rh[0] * d[0] + rh[1] * d[1] + rh[2] * d[2], -1.0, 1.0);
  const double psi = std::acos(c);
  if (psi > 1e-9) {
    const double delta = 2.0 * M / rho * std::tan(0.5 * psi);
    // Unit vector in the plane, perpendicular to d, pointing away from the centre side.
    Vec3 w = {rh[0] - c * d[0], rh[1] - c * d[1], rh[2] - c * d[2]};
    const double wn = norm3(w);
    for (auto& q : w) q /= wn;
    const double cd = std::cos(delta), sd = std::sin(delta);
    d = {cd * d[0] - sd * w[0], cd * d[1] - sd * w[1], cd * d[2] - sd * w[2]};
  }
  return d;
}

}  // namespace lc
