#pragma once
// Null geodesics of Kerr in Boyer–Lindquist coordinates and Mino time: the
// fast path for rays through Kerr scenes without moving objects
// (docs/physics.md, "Two integrators for Kerr").
//
// With the constants E = -p_t, L = p_phi and Carter's K = Q + (L - a E)^2,
// and Mino time lambda (d lambda = d sigma / Sigma, sigma affine), the radial
// and polar motions separate (Carter 1968, Phys. Rev. 174, 1559; Mino 2003,
// Phys. Rev. D 67, 084027).  In u = 1/r:
//   (du/dl)^2  = U(u)  = Pu^2 - u^2 D K,   Pu = E + a (a E - L) u^2,  D = 1 - 2 M u + a^2 u^2
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
// Regular wherever rays go: L = 0 rays (all those from an observer on the
// spin axis) cross the axis with sin th changing sign, which stands for the
// same point at (-th, phi + pi); rays with L != 0 turn before the axis.  BL
// is singular at the horizon, but rays are stopped at the capture radius,
// well outside it.  Valid for M > 0 and M = 0 alike.

#include <array>
#include <cmath>

#include "core/constants.hpp"
#include "geodesic/dormand_prince.hpp"
#include "geodesic/null_ray.hpp"
#include "geodesic/stop_reason.hpp"

namespace lc {

// t, u = 1/r, cos th, sin th, phi, du/dl, dth/dl, sigma (the affine parameter).
using MinoState = std::array<double, 8>;
using MinoStep = DenseStep<8>;

// The right-hand side for one ray: the spacetime and the ray's constants.
struct KerrMinoRhs {
  double M, a, E, L, K;
  double a2, aE, a2E2, L2, alpha;  // alpha = a (a E - L)
  double u_floor2;                 // t and sigma are followed out to r = 1 / u_floor only

  KerrMinoRhs(double mass, double spin, double energy, double ang_mom, double carter_k, double u_floor)
      : M(mass), a(spin), E(energy), L(ang_mom), K(carter_k), a2(spin * spin), aE(spin * energy),
        a2E2(spin * spin * energy * energy), L2(ang_mom * ang_mom), alpha(spin * (spin * energy - ang_mom)),
        u_floor2(u_floor * u_floor) {}

  // Inputs: Mino time (unused: Kerr is stationary) and the state; output
  // its derivative.  Assumes r outside the horizon and sin th != 0 unless
  // L = 0.  u may reach 0 and below: the motion in u, th and phi continues
  // analytically through infinity (which is how an escaping ray's direction
  // at infinity is found), while t and sigma, which grow as 1/u there, stop
  // being followed beyond 1 / u_floor.
  void operator()(double, const MinoState& y, MinoState& dy) const {
    const double u = y[1], c = y[2], s = y[3], U = y[5], w = y[6];
    const double u2 = u * u;
    const double Pu = E + alpha * u2;
    const double inv_D = 1.0 / (1.0 - 2.0 * M * u + a2 * u2);
    const double inv_u2 = 1.0 / std::max(u2, u_floor2);
    const double s2 = s * s;
    const double L_s2 = L == 0.0 ? 0.0 : L / s2;  // L / sin^2 (0 on the axis when L = 0)
    dy[0] = a * (L - aE * s2) + (1.0 + a2 * u2) * Pu * inv_D * inv_u2;
    dy[1] = U;
    dy[2] = -s * w;
    dy[3] = c * w;
    dy[4] = L_s2 - aE + a * Pu * inv_D;
    dy[5] = 2.0 * alpha * u * Pu - K * u * (1.0 - 3.0 * M * u + 2.0 * a2 * u2);
    dy[6] = c * s * (L_s2 * L_s2 - a2E2);  // c (L^2 / s^3 - a^2 E^2 s)
    dy[7] = inv_u2 + a2 * c * c;           // d sigma / d lambda = Sigma
  }
};

struct MinoResult {
  StopReason reason = StopReason::gave_up;
  MinoState y{};
  double lambda = 0.0;  // Mino time at the end
  long steps = 0;
};

// A ray's start: its constants and initial state, from a Boyer–Lindquist
// event s = (t, r, th, phi) and covariant momentum p (BL components, any
// time orientation).  On the axis (sin th = 0) p_phi must be 0, as it is
// for any momentum there; it is then taken as exactly 0.  t and sigma are
// followed out to twice `escape_radius`.
struct KerrMinoStart {
  KerrMinoRhs rhs;
  MinoState y0;
};
inline KerrMinoStart kerr_mino_start(double M, double a, const Vec4& s, const Vec4& p,
                                     double escape_radius = default_escape_radius) {
  const double r = s[1], c = std::cos(s[2]), sn = std::sin(s[2]);
  const double E = -p[0];
  const double L = sn == 0.0 ? 0.0 : p[3];
  const double u = 1.0 / r;
  const double D = 1.0 - 2.0 * M * u + a * a * u * u;  // Delta / r^2
  const double Q = p[2] * p[2] - a * a * E * E * c * c + (L == 0.0 ? 0.0 : L * L * c * c / (sn * sn));
  const double K = Q + (L - a * E) * (L - a * E);
  // du/dl = -u^2 dr/dl = -u^2 Delta p_r = -D p_r.
  return {KerrMinoRhs(M, a, E, L, K, 0.5 / escape_radius), {s[0], u, c, sn, s[3], -D * p[1], p[2], 0.0}};
}

// The BL event and covariant momentum of a state, with th in [0, pi] and
// phi in [0, 2 pi) (a state with sin th < 0 is the point (-th, phi + pi)).
inline void kerr_mino_event(const KerrMinoRhs& k, const MinoState& y, Vec4& s, Vec4& p) {
  const bool flip = y[3] < 0.0;
  const double th = std::atan2(std::abs(y[3]), y[2]);
  double phi = std::fmod(y[4] + (flip ? pi : 0.0), two_pi);
  if (phi < 0.0) phi += two_pi;
  if (phi >= two_pi) phi = 0.0;
  const double u = y[1];
  const double D = 1.0 - 2.0 * k.M * u + k.a2 * u * u;
  s = {y[0], 1.0 / u, th, phi};
  p = {-k.E, -y[5] / D, flip ? -y[6] : y[6], k.L};
}

// Integrates from `start` with Dormand–Prince 5(4) until the ray is captured
// (r below `capture_radius`), reaches infinity (u <= 0: StopReason::escaped;
// the last step spans u = 0, where the visitor finds the direction at
// infinity), is stopped by the visitor (visit(const MinoStep&, MinoResult&)
// returning true after an accepted step, having set the reason), or runs out
// of steps.  Mino time runs the same way as the affine parameter of
// `start`'s momentum.
template <class Visitor>
MinoResult trace_kerr_mino(const KerrMinoStart& start, double capture_radius, const RayOptions& opt, Visitor&& visit) {
  // t and sigma are passive (nothing depends on them) and grow without
  // bound: they do not steer the step size.
  const MinoState weights = {0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0};
  DormandPrince5<8, const KerrMinoRhs&> dp(start.rhs, opt.control, weights);
  // Mino time runs ~ 1/r^2 of the affine parameter: the same first step as
  // the Kerr–Schild path takes in sigma.
  dp.reset(0.0, start.y0, 1e-2 * std::min(1.0, start.y0[1]));
  const double u_capture = capture_radius > 0.0 ? 1.0 / capture_radius : 1e300;
  MinoResult res;
  MinoStep step;
  while (true) {
    if (res.steps >= opt.max_steps) {
      res.reason = StopReason::step_limit;
      break;
    }
    if (!dp.step(step)) {
      res.reason = StopReason::gave_up;
      break;
    }
    ++res.steps;
    if (dp.y()[1] <= 0.0) res.reason = StopReason::escaped;  // the visitor sees the step that reaches infinity
    if (visit(step, res)) return res;
    if (res.reason == StopReason::escaped) break;
    if (dp.y()[1] > u_capture) {
      res.reason = StopReason::horizon;
      break;
    }
  }
  res.y = dp.y();
  res.lambda = dp.t();
  return res;
}

}  // namespace lc
