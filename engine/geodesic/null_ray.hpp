#pragma once
// Null geodesics in Hamiltonian form (x^mu, p_mu) in a spacetime's trace
// chart, as run_rays (geodesic/ray_loop.hpp) integrates them: the right-hand
// side is the spacetime's own (S::rhs, on doubles or lanes), a ray is
// captured where S::captured holds (and ends on the capture surface), and
// it has escaped where the spacetime says it reached a far end (S::flight,
// given the escape and free-flight radii).  Templated on
// the concrete spacetime: no virtual call or allocation per step.

#include <cmath>
#include <optional>

#include "core/constants.hpp"
#include "core/tensor.hpp"
#include "geodesic/crossing.hpp"
#include "geodesic/ray_loop.hpp"

namespace lc {

// How Kerr rays are integrated: in Boyer–Lindquist coordinates with Mino
// time (geodesic/kerr_mino.hpp; the fast path, used when a scene has no
// moving objects) or always with the Kerr–Schild Hamiltonian.
enum class KerrChart { boyer_lindquist_mino, kerr_schild };

// Where a ray moving outwards stops being integrated (the sky lookup then
// adds the bending still to come: the spacetime's escape direction).
enum class EscapeRule {
  far_field,  // the scene builder may bring escape_radius in to where the rest is known (far_field_bending)
  fixed,      // always at escape_radius (references)
};

struct RayOptions {
  StepControl control{default_ray_tolerance, default_ray_tolerance, 1e-12, 1e30};
  KerrChart kerr_chart = KerrChart::boyer_lindquist_mino;
  // How far out a ray has reached a far end, in the spacetime's own radial
  // measure (S::flight; the Cartesian radius of the trace chart for
  // CartesianInfinity).
  double escape_radius = default_escape_radius;
  EscapeRule escape = EscapeRule::far_field;
  // Beyond this radius (the same measure), moving on, a ray meets nothing more
  // (the scene builder sets it from the objects and the holes; 0: never):
  // its tolerances are relaxed by free_flight_relaxation.
  double free_radius = 0.0;
  long max_steps = default_max_steps;
};

// The squared radii of a ray's options as S::flight takes them (a free
// radius of 0: never free).
inline FlightRadii flight_radii(const RayOptions& opt) {
  return {opt.free_radius > 0.0 ? opt.free_radius * opt.free_radius : 1e300, opt.escape_radius * opt.escape_radius};
}

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

// The Hamiltonian formulation for run_rays, with rays of type RayT (each
// provides start(), slope(), first_step() and visit()).
template <class S, class RayT>
struct HamiltonianPath {
  using Ray = RayT;
  // S's right-hand side on Lanes<W>; no per-ray constants.
  template <int W>
  struct Rhs {
    const S& st;
    explicit Rhs(const HamiltonianPath& p) : st(p.st) {}
    void load(int, const Ray&) {}
    void operator()(Lanes<W>, const std::array<Lanes<W>, 8>& y, std::array<Lanes<W>, 8>& dy) const { st.rhs(y, dy); }
  };
  // Coordinate time and p_t are passive in stationary spacetimes (nothing
  // depends on them and p_t is constant), so they do not steer the step size:
  // near a Kerr–Schild horizon t diverges logarithmically and would stall it.
  static constexpr RayState weights = {0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0};

  const S& st;
  FlightRadii radii;  // squared free-flight and escape radii

  HamiltonianPath(const S& spacetime, const RayOptions& opt) : st(spacetime), radii(flight_radii(opt)) {}

  // An idle lane's state: far out, moving on; its right-hand side is finite.
  static RayState idle() { return {0, 0, 1e3, 0, 1, 0, 1, 0}; }
  RayState idle_slope() const {
    RayState dy;
    st.rhs(idle(), dy);
    return dy;
  }
  template <class Y>
  bool at_infinity(const Y&) const {
    return false;
  }
  template <class Y>
  bool captured(const Y& y) const {
    return st.captured({y(0), y(1), y(2), y(3)});
  }
  bool capture_crossing(const RayStep& step, RayResult& res) const {
    res.lambda = lc::capture_crossing(st, step);
    res.y = step.at(res.lambda);
    return true;
  }
  template <class Y, class D>
  Flight flight(const Y& y, const D& dy) const {
    return st.flight(y, dy, radii);
  }
};

// No-op visitor: trace until capture or escape.
struct NoObjects {
  bool operator()(const RayStep&, RayResult&) const { return false; }
};

// What trace_null_ray gives: the result, and H = 1/2 g(k, k) at the end (0
// for light; its size is the drift).
struct NullRayResult : RayResult {
  double hamiltonian = 0.0;
};

// One ray from x0 with covariant momentum p0 along increasing affine
// parameter (pass a past-directed p0 to trace backwards in time), in the
// one ray loop.  After each accepted step the visitor sees the step's dense
// output and may stop the ray (return true) after filling in the result.
// Assumes x0 is outside any capture region.  For tests and tools; the
// renderer's rays are render/trace.hpp's.
template <class S, class Visitor = NoObjects>
NullRayResult trace_null_ray(const S& st, const Vec4& x0, const Vec4& p0, const RayOptions& opt,
                             Visitor&& visit = Visitor{}) {
  struct Ray {
    const S& st;
    RayState y0;
    Visitor& v;
    RayState start() const { return y0; }
    RayState slope() const {
      RayState dy;
      st.rhs(y0, dy);
      return dy;
    }
    double first_step() const { return 1e-2 * std::max(1.0, std::sqrt(y0[1] * y0[1] + y0[2] * y0[2] + y0[3] * y0[3])); }
    bool visit(const RayStep& step, RayResult& res) { return v(step, res); }
  };
  const HamiltonianPath<S, Ray> path(st, opt);
  NullRayResult out;
  run_rays<1>(
      path, opt.control, opt.max_steps, 1,
      [&](std::size_t, std::optional<Ray>& slot) {
        slot.emplace(Ray{st, {x0[0], x0[1], x0[2], x0[3], p0[0], p0[1], p0[2], p0[3]}, visit});
      },
      [&](std::size_t, const Ray&, const RayResult& res) { static_cast<RayResult&>(out) = res; });
  RayState dy;
  st.rhs(out.y, dy);
  out.hamiltonian = 0.5 * (out.y[4] * dy[0] + out.y[5] * dy[1] + out.y[6] * dy[2] + out.y[7] * dy[3]);
  return out;
}

}  // namespace lc
