#pragma once
// The per-pixel hot loop: one null geodesic in Hamiltonian form
// (x^mu, p_mu), integrated with Dormand–Prince 5(4) until it is captured,
// escapes, is stopped by the caller's visitor (an object hit), or runs out of
// steps.  Templated on the concrete spacetime: no virtual call or allocation
// per step.

#include <cmath>

#include "core/constants.hpp"
#include "core/tensor.hpp"
#include "geodesic/crossing.hpp"
#include "geodesic/dormand_prince.hpp"
#include "geodesic/stop_reason.hpp"

namespace lc {

using RayState = std::array<double, 8>;  // x^0..x^3, p_0..p_3
using RayStep = DenseStep<8>;

// How Kerr rays are integrated: in Boyer–Lindquist coordinates with Mino
// time (geodesic/kerr_mino.hpp; the fast path, used when a scene has no
// moving objects) or always with the Kerr–Schild Hamiltonian.
enum class KerrChart { boyer_lindquist_mino, kerr_schild };

// Where a ray moving outwards stops being integrated (the sky lookup then
// adds the bending still to come, render/scene.hpp's sky_sample).
enum class EscapeRule {
  far_field,  // the scene builder may bring escape_radius in to where the rest is known (far_field_bending)
  fixed,      // always at escape_radius (references)
};

struct RayOptions {
  StepControl control{default_ray_tolerance, default_ray_tolerance, 1e-12, 1e30};
  KerrChart kerr_chart = KerrChart::boyer_lindquist_mino;
  double escape_radius = default_escape_radius;
  EscapeRule escape = EscapeRule::far_field;
  // Beyond this coordinate radius, moving outwards, a ray meets nothing more
  // (the scene builder sets it from the objects and the holes; 0: never):
  // its tolerances are relaxed by free_flight_relaxation.
  double free_radius = 0.0;
  long max_steps = default_max_steps;
};

struct RayResult {
  StopReason reason = StopReason::gave_up;
  RayState y{};       // final state (at the hit for StopReason::hit, set by the visitor)
  double lambda = 0.0;
  long steps = 0;
  double hamiltonian = 0.0;  // H = 1/2 g(k, k) at the end: 0 for light; its size is the drift
};

// No-op visitor: trace until capture or escape.
struct NoObjects {
  bool operator()(const RayStep&, RayResult&) const { return false; }
};

// Where within `step`, which ends captured (S::captured), the ray crossed
// into the capture region: the data layers' event of a horizon pixel is on
// the capture surface, not wherever the step happened to end (for
// Schwarzschild that was inside the horizon).
template <class S>
double capture_crossing(const S& st, const RayStep& step) {
  auto margin = [&st](const RayState& y) { return st.capture_margin({y[0], y[1], y[2], y[3]}); };
  const double m0 = margin(step.start()), m1 = margin(step.at(step.t0 + step.h));
  if (!(m0 > 0.0)) return step.t0;  // started captured (cannot happen from outside)
  return locate_crossing(step, margin, m0, m1, 1e-12);
}

// Traces from x0 with covariant momentum p0 along increasing affine
// parameter (pass a past-directed p0 to trace backwards in time).  After each
// accepted step the visitor sees the step's dense output and may stop the ray
// (return true) after filling in the result.  Assumes x0 is outside any
// capture region.
template <class S, class Visitor = NoObjects>
RayResult trace_null_ray(const S& st, const Vec4& x0, const Vec4& p0, const RayOptions& opt,
                         Visitor&& visit = Visitor{}) {
  auto rhs = [&st](double, const RayState& y, RayState& dy) {
    Vec4 dx, dp;
    st.hamiltonian_rhs({y[0], y[1], y[2], y[3]}, {y[4], y[5], y[6], y[7]}, dx, dp);
    dy = {dx[0], dx[1], dx[2], dx[3], dp[0], dp[1], dp[2], dp[3]};
  };
  // Coordinate time and p_t are passive in stationary spacetimes (nothing
  // depends on them and p_t is constant), so they do not steer the step size:
  // near a Kerr–Schild horizon t diverges logarithmically and would stall it.
  const RayState weights = {0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0};
  DormandPrince5<8, decltype(rhs)> dp(rhs, opt.control, weights);
  const RayState y0 = {x0[0], x0[1], x0[2], x0[3], p0[0], p0[1], p0[2], p0[3]};
  const double rho0 = std::sqrt(x0[1] * x0[1] + x0[2] * x0[2] + x0[3] * x0[3]);
  dp.reset(0.0, y0, 1e-2 * std::max(1.0, rho0));

  RayResult res;
  RayStep step;
  const double R2 = opt.escape_radius * opt.escape_radius;
  const double free2 = opt.free_radius > 0.0 ? opt.free_radius * opt.free_radius : 1e300;
  StepControl relaxed_control = opt.control;
  relaxed_control.rtol *= free_flight_relaxation;
  relaxed_control.atol *= free_flight_relaxation;
  bool relaxed = false;
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
    if (visit(step, res)) return res;
    const RayState& y = dp.y();
    const Vec4 x = {y[0], y[1], y[2], y[3]};
    if (st.captured(x)) {
      res.reason = StopReason::horizon;
      res.lambda = capture_crossing(st, step);
      res.y = step.at(res.lambda);
      Vec4 dx, dp_;
      st.hamiltonian_rhs({res.y[0], res.y[1], res.y[2], res.y[3]}, {res.y[4], res.y[5], res.y[6], res.y[7]}, dx, dp_);
      res.hamiltonian = 0.5 * (res.y[4] * dx[0] + res.y[5] * dx[1] + res.y[6] * dx[2] + res.y[7] * dx[3]);
      return res;
    }
    const double rho2 = y[1] * y[1] + y[2] * y[2] + y[3] * y[3];
    if (!relaxed && rho2 > free2) {
      const auto& d = dp.dydt();
      if (y[1] * d[1] + y[2] * d[2] + y[3] * d[3] > 0.0) {
        dp.set_control(relaxed_control);
        relaxed = true;
      }
    }
    if (rho2 > R2) {
      const auto& d = dp.dydt();
      if (y[1] * d[1] + y[2] * d[2] + y[3] * d[3] > 0.0) {
        res.reason = StopReason::escaped;
        break;
      }
    }
  }
  res.y = dp.y();
  res.lambda = dp.t();
  const auto& d = dp.dydt();
  res.hamiltonian = 0.5 * (res.y[4] * d[0] + res.y[5] * d[1] + res.y[6] * d[2] + res.y[7] * d[3]);
  return res;
}

}  // namespace lc
