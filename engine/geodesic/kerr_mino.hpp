#pragma once
// Null geodesics of Kerr in Boyer–Lindquist coordinates and Mino time: the
// fast path for rays through Kerr scenes without moving objects
// (docs/physics.md, "Two integrators for Kerr").
//
// With the constants E = -p_t, L = p_phi and Carter's K = Q + (L - a E)^2
// (Q Carter's constant; the hole's charge is e below), and Mino time lambda (d lambda = d sigma / Sigma, sigma affine), the radial
// and polar motions separate (Carter 1968, Phys. Rev. 174, 1559; Mino 2003,
// Phys. Rev. D 67, 084027).  In u = 1/r:
//   (du/dl)^2  = U(u)  = Pu^2 - u^2 D K,   Pu = E + a (a E - L) u^2,  D = 1 - 2 M u + (a^2 + e^2) u^2
//   (dth/dl)^2 = Theta = Q + a^2 E^2 cos^2 - L^2 cot^2
//   dphi/dl    = L / sin^2 - a E + a Pu / D
//   dt/dl      = a (L - a E sin^2) + (1 + a^2 u^2) Pu / (u^2 D)
// The radial motion is polynomial in u — in flat space a harmonic
// oscillation, u'' = -K u — where in r it has a pole at infinity that costs
// hundreds of steps to approach.  Both motions are integrated in
// second-order form (u'' = U'/2, th'' = Theta'/2), so turning points need no
// sign bookkeeping, with cos th and sin th carried as state (d cos = -sin w,
// d sin = cos w): no trigonometry, no square root and two divisions per
// evaluation.  E, L and K are exact constants here; only U = (du/dl)^2 and
// Theta = w^2 can drift.
//
// Coordinate time is passive (it steers no step), and dt/dl has poles where
// rays end: ~E/u^2 as an escaping ray's u runs to 0 within one long step,
// ~1/Delta at the horizon, and between them it grows like r^2 along legs
// that u crosses in a few steps.  Steps sized by the other components
// cannot follow that (t came out ~6000 M off at the escape radius and
// ~2 M off at the capture radius).  The state carries instead
//   tau = t - sgn(Pu) V,   dV/dl = |du/dl| (1 + a^2 u^2) / (u^2 D) = |dr*/dl|,
// V the variation of the tortoise radius r* (dr*/dr = (r^2 + a^2)/Delta)
// along the ray so far (Pu keeps its sign along a ray outside the horizon:
// U^2 = Pu^2 - u^2 D K would be negative where it vanished).  With
// |du/dl| = W = sqrt(Pu^2 - u^2 D K),
//   dtau/dl = a (L - a E sin^2) + sgn(Pu) (1 + a^2 u^2) K / (|Pu| + W),
// which has no pole at all: t comes out to ~1e-6 M (docs/layers.md).  (W
// comes from u, not from the state's du/dl: a stage's du/dl is off by its
// truncation error, which a 1/u^2 would multiply.)  V is exact: r* changes
// monotonically between radial turning points, which MinoClock finds.
//
// Regular wherever rays go: L = 0 rays (all those from an observer on the
// spin axis) cross the axis with sin th changing sign, which stands for the
// same point at (-th, phi + pi); rays with L != 0 turn before the axis.  BL
// is singular at the horizon, but rays are stopped at the capture radius,
// well outside it.  Valid for M > 0 and M = 0 alike, and for a charged
// (Kerr–Newman) hole of charge e: the charge enters only through
// D = Delta / r^2 (the separation and Carter's constant survive it: Carter
// 1968), as d = a^2 + e^2 where D has a^2; at e = 0 d is a^2 exactly.

#include <array>
#include <cmath>

#include "core/constants.hpp"
#include "geodesic/ray_loop.hpp"
#include "geodesic/crossing.hpp"
#include "geodesic/stop_reason.hpp"
#include "spacetime/kerr.hpp"

namespace lc {

// tau (coordinate time less sgn(E) V, see above), u = 1/r, cos th, sin th,
// phi, du/dl, dth/dl, sigma (the affine parameter).
using MinoState = std::array<double, 8>;
using MinoStep = DenseStep<8>;

// One ray's constants of motion and of the chart (doubles).
struct KerrMinoConstants {
  double M, a, e, E, L, K;            // e: the hole's charge
  double a2, d, aE, a2E2, L2, alpha;  // d = a^2 + e^2, alpha = a (a E - L)
  double u_floor2;                 // t and sigma are followed out to r = 1 / u_floor only
  double sign_P = 1.0;             // sgn(Pu): tau = t - sgn(Pu) V

  KerrMinoConstants(double mass, double spin, double charge, double energy, double ang_mom, double carter_k,
                    double u_floor)
      : M(mass), a(spin), e(charge), E(energy), L(ang_mom), K(carter_k), a2(spin * spin),
        d(spin * spin + charge * charge), aE(spin * energy),
        a2E2(spin * spin * energy * energy), L2(ang_mom * ang_mom), alpha(spin * (spin * energy - ang_mom)),
        u_floor2(u_floor * u_floor) {}
};

// The right-hand side on T = double (one ray) or a vector of lanes
// (core/lanes.hpp), lane i holding the constants of the ray set() there
// (zeros before: a finite right-hand side for an idle lane).
template <class T>
struct KerrMinoRhs {
  T M{}, a{}, E{}, L{}, K{}, a2{}, d{}, aE{}, a2E2{}, alpha{}, u_floor2{}, sign_P{};

  void set(int i, const KerrMinoConstants& k) {
    set_lane(M, i, k.M);
    set_lane(a, i, k.a);
    set_lane(E, i, k.E);
    set_lane(L, i, k.L);
    set_lane(K, i, k.K);
    set_lane(a2, i, k.a2);
    set_lane(d, i, k.d);
    set_lane(aE, i, k.aE);
    set_lane(a2E2, i, k.a2E2);
    set_lane(alpha, i, k.alpha);
    set_lane(u_floor2, i, k.u_floor2);
    set_lane(sign_P, i, k.sign_P);
  }

  // Inputs: Mino time (unused: Kerr is stationary) and the state; output
  // its derivative.  Assumes r outside the horizon and sin th != 0 unless
  // L = 0.  u may reach 0 and below: the motion in u, th and phi continues
  // analytically through infinity (which is how an escaping ray's direction
  // at infinity is found), while sigma, which grows as 1/u there, stops
  // being followed beyond 1 / u_floor.
  void operator()(T, const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    const T zero = T{} + 0.0, one = T{} + 1.0;
    const T u = y[1], c = y[2], s = y[3], U = y[5], w = y[6];
    const T u2 = u * u;
    const T Pu = E + alpha * u2;
    const T inv_D = one / (one - 2.0 * M * u + d * u2);
    const T inv_u2 = one / (u2 > u_floor2 ? u2 : u_floor2);
    const T s2 = s * s;
    const T L_s2 = L == zero ? zero : L / s2;  // L / sin^2 (0 on the axis when L = 0)
    const T W2 = Pu * Pu - u2 * (one - 2.0 * M * u + d * u2) * K;
    const T W = sqrt_of(W2 > zero ? W2 : zero);
    dy[0] = a * (L - aE * s2) + sign_P * (one + a2 * u2) * K / (abs_of(Pu) + W);
    dy[1] = U;
    dy[2] = -s * w;
    dy[3] = c * w;
    dy[4] = L_s2 - aE + a * Pu * inv_D;
    dy[5] = 2.0 * alpha * u * Pu - K * u * (one - 3.0 * M * u + 2.0 * d * u2);
    dy[6] = c * s * (L_s2 * L_s2 - a2E2);  // c (L^2 / s^3 - a^2 E^2 s)
    dy[7] = inv_u2 + a2 * c * c;           // d sigma / d lambda = Sigma
  }
};

// Mino time, the end state in MinoState form: run_rays' result.
using MinoResult = RayResult;

// A ray's start: its constants and initial state, from a Boyer–Lindquist
// event s = (t, r, th, phi) and covariant momentum p (BL components, any
// time orientation).  On the axis (sin th = 0) p_phi must be 0, as it is
// for any momentum there; it is then taken as exactly 0.  t and sigma are
// followed out to twice `escape_radius`.
struct KerrMinoStart {
  KerrMinoConstants k;
  MinoState y0;
  // The slope at the start.
  MinoState slope() const {
    KerrMinoRhs<double> rhs;
    rhs.set(0, k);
    MinoState dy;
    rhs(0.0, y0, dy);
    return dy;
  }
  // The first trial step in Mino time: ~1/r^2 of the affine parameter, so
  // the same as the Kerr–Schild path's first step in sigma.
  double first_step() const { return 1e-2 * std::min(1.0, y0[1]); }
};
inline KerrMinoStart kerr_mino_start(double M, double a, double charge, const Vec4& s, const Vec4& p,
                                     double escape_radius = default_escape_radius) {
  const double r = s[1], c = std::cos(s[2]), sn = std::sin(s[2]);
  const double E = -p[0];
  const double L = sn == 0.0 ? 0.0 : p[3];
  const double u = 1.0 / r;
  const double D = 1.0 - 2.0 * M * u + (a * a + charge * charge) * u * u;  // Delta / r^2
  const double Q = p[2] * p[2] - a * a * E * E * c * c + (L == 0.0 ? 0.0 : L * L * c * c / (sn * sn));
  const double K = Q + (L - a * E) * (L - a * E);
  KerrMinoConstants k(M, a, charge, E, L, K, 0.5 / escape_radius);
  k.sign_P = E + k.alpha * u * u < 0.0 ? -1.0 : 1.0;
  // du/dl = -u^2 dr/dl = -u^2 Delta p_r = -D p_r.
  return {k, {s[0], u, c, sn, s[3], -D * p[1], p[2], 0.0}};
}

// The BL event and covariant momentum of a state, with th in [0, pi] and
// phi in [0, 2 pi) (a state with sin th < 0 is the point (-th, phi + pi)),
// and s[0] = tau: MinoClock::time gives t.
inline void kerr_mino_event(const KerrMinoConstants& k, const MinoState& y, Vec4& s, Vec4& p) {
  const bool flip = y[3] < 0.0;
  const double th = std::atan2(std::abs(y[3]), y[2]);
  double phi = std::fmod(y[4] + (flip ? pi : 0.0), two_pi);
  if (phi < 0.0) phi += two_pi;
  if (phi >= two_pi) phi = 0.0;
  const double u = y[1];
  const double D = 1.0 - 2.0 * k.M * u + k.d * u * u;
  s = {y[0], 1.0 / u, th, phi};
  p = {-k.E, -y[5] / D, flip ? -y[6] : y[6], k.L};
}

// Coordinate time along one Mino ray: t = tau + sgn(Pu) V (see above), V
// kept leg by leg between radial turning points.  see() is shown every
// accepted step before times in it are asked for; time() then holds for
// any point of that step (before or after a turning point in it) and of the
// steps before it on the same leg.
class MinoClock {
 public:
  MinoClock(const KerrMinoConstants& k, double u0) : k_(k), u_leg_(u0), r_star_leg_(r_star(u0)) {}

  // The step [step.t0, l1] (l1 <= its end): closes the previous step's turn
  // and finds this one's, where du/dl changes sign (one per step at most:
  // null rays turn once outside the photon region).
  void see(const MinoStep& step, double l1) {
    if (turn_) {
      variation_ += std::abs(turn_r_star_ - r_star_leg_);
      r_star_leg_ = turn_r_star_;
      turn_ = false;
    }
    const double U0 = step.start()[5], U1 = step.component(5, l1);
    if (U0 == 0.0 || (U0 > 0.0) == (U1 > 0.0)) return;
    turn_lambda_ = locate_crossing(step, [](const MinoState& y) { return y[5]; }, step.t0, l1, U0, U1);
    turn_r_star_ = r_star(step.component(1, turn_lambda_));
    turn_ = true;
  }

  // t at the state y at Mino time lambda, in the step last seen.
  double time(const MinoState& y, double lambda) const {
    double v = variation_;
    double from = r_star_leg_;
    if (turn_ && lambda > turn_lambda_) {
      v += std::abs(turn_r_star_ - from);
      from = turn_r_star_;
    }
    return y[0] + k_.sign_P * (v + std::abs(r_star(y[1]) - from));
  }

 private:
  double r_star(double u) const { return 1.0 / u + kerr_radial_time(k_.M, k_.a, k_.e, 1.0 / u); }

  const KerrMinoConstants& k_;
  double u_leg_;
  double r_star_leg_;        // r* where the current leg began
  double variation_ = 0.0;   // V over the legs before it
  bool turn_ = false;        // the step last seen turns at turn_lambda_
  double turn_lambda_ = 0.0, turn_r_star_ = 0.0;
};

// The BL–Mino formulation for run_rays (geodesic/ray_loop.hpp), with rays of
// type RayT (each provides constants() besides start(), slope(),
// first_step() and visit()).  A ray reaches infinity in the step where u
// falls to 0 or below (its visitor finds the direction there) and is
// captured below the capture radius; its visitor keeps the capture event
// itself (the time needs MinoClock).  There is no free flight: the steps
// out to infinity are few and long already.
template <class RayT>
struct MinoPath {
  using Ray = RayT;
  template <int W>
  struct Rhs : KerrMinoRhs<Lanes<W>> {
    explicit Rhs(const MinoPath&) {}
    void load(int i, const Ray& r) { this->set(i, r.constants()); }
  };
  // tau and sigma are passive (nothing depends on them) and grow without
  // bound: they do not steer the step size.
  static constexpr MinoState weights = {0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0};

  double u_capture;  // 1 / capture radius (1e300: nothing is captured)

  static MinoState idle() { return {0, 0.01, 0, 1, 0, 0, 0, 0}; }  // a finite right-hand side
  static MinoState idle_slope() { return {}; }
  template <class Y>
  bool at_infinity(const Y& y) const {
    return y(1) <= 0.0;
  }
  template <class Y>
  bool captured(const Y& y) const {
    return y(1) > u_capture;
  }
  bool capture_crossing(const MinoStep&, RayResult&) const { return false; }
  template <class Y, class D>
  Flight flight(const Y&, const D&) const {
    return {};
  }
};

// One ray from `start` in the one ray loop, until it is captured (r below
// `capture_radius`, 0: never), reaches infinity (u <= 0: StopReason::
// escaped; the last step spans u = 0), is stopped by the visitor
// (visit(const MinoStep&, MinoResult&) returning true after an accepted
// step, having set the reason), or runs out of steps.  Mino time runs the
// same way as the affine parameter of `start`'s momentum.  For tests; the
// renderer's rays are render/trace.hpp's.
template <class Visitor>
MinoResult trace_kerr_mino(const KerrMinoStart& start, double capture_radius, const StepControl& control,
                           long max_steps, Visitor&& visit) {
  struct Ray {
    const KerrMinoStart& s;
    Visitor& v;
    const KerrMinoConstants& constants() const { return s.k; }
    MinoState start() const { return s.y0; }
    MinoState slope() const { return s.slope(); }
    double first_step() const { return s.first_step(); }
    bool visit(const MinoStep& step, RayResult& res) { return v(step, res); }
  };
  const MinoPath<Ray> path{capture_radius > 0.0 ? 1.0 / capture_radius : 1e300};
  MinoResult out;
  run_rays<1>(
      path, control, max_steps, 1, [&](std::size_t, std::optional<Ray>& slot) { slot.emplace(Ray{start, visit}); },
      [&](std::size_t, const Ray&, const RayResult& res) { out = res; });
  return out;
}

}  // namespace lc
