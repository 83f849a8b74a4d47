#pragma once
// One camera ray through a scene in the general path (render/trace.hpp):
// Hamilton's equations in the spacetime's trace chart, with the visitor that
// tests each step against the spheres and the disk, counts equatorial
// crossings (hit.order) and, at the end, looks up the sky or reports the
// horizon.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "geodesic/crossing.hpp"
#include "spacetime/weak_field_tail.hpp"
#include "observer/ray_direction.hpp"
#include "observer/tetrad.hpp"
#include "render/hit.hpp"
#include "render/scene.hpp"
#include "spacetime/chart.hpp"

namespace lc {

// For trace_sample: a path recorder that records nothing (rendering).
struct NoPath {
  void operator()(const RayState&, double) const {}
};

namespace detail {

// The sky seen by a ray that escaped at the trace-coordinate event x with
// momentum p: fills out.kind and out.color, and sky's direction.
template <class S>
void sky_sample(const SceneIn<S>& sc, const Vec4& x, const Vec4& p, RayHit& out, SkyPoint& sky) {
  const S& st = sc.spacetime;
  // Escape direction: the spatial tangent, bent by the deflection still to
  // come between here and infinity (the spacetime's far field).
  Vec4 dx, dp;
  st.hamiltonian_rhs(x, p, dx, dp);
  Vec3 d = {dx[1], dx[2], dx[3]};
  const double dn = norm3(d);
  for (auto& c : d) c /= dn;
  d = st.escape_direction(x, d);
  out.kind = HitKind::sky;
  const double theta = std::acos(std::clamp(d[2], -1.0, 1.0));
  double sphi = std::atan2(d[1], d[0]);
  if (sphi < 0) sphi += two_pi;
  out.color = sc.sky.color(theta, sphi);
  sky.theta = theta;
  sky.phi = sphi;
}


// The general path: the Hamiltonian in the trace chart (Kerr–Schild for
// Kerr).  One ray's start, its visitor (spheres, the disk, plane crossings)
// and its result; run_rays (geodesic/ray_loop.hpp) integrates it, alone or
// beside others in vector lanes (render/trace.hpp).
template <class S, class OnStep>
class HamiltonianRay {
 public:
  HamiltonianRay(const SceneIn<S>& sc, const Vec3& n, OnStep& on_step)
      : sc_(sc), on_step_(on_step), p0_(backward_ray_momentum(sc.metric, sc.frame, n)) {
    // No other frame can reuse a ray of a frame without a still key.
    if (sc.still_key.empty()) out_.reuse_window = 0.0f;
  }

  const Vec4& momentum() const { return p0_; }
  // Whether the objects work out for how long another frame could reuse
  // the ray (RayHit::reuse_window); if not, a ray that comes near a moving
  // object's path gets 0 at once and the others stay unlimited.
  void track_reuse_windows(bool track) { track_windows_ = track && track_windows_; }
  // What run_rays starts the ray with.
  RayState start() const {
    const Vec4& x0 = sc_.observer;
    return {x0[0], x0[1], x0[2], x0[3], p0_[0], p0_[1], p0_[2], p0_[3]};
  }
  RayState slope() const {
    RayState dy;
    sc_.spacetime.rhs(start(), dy);
    return dy;
  }
  double first_step() const {
    const Vec4& x0 = sc_.observer;
    return 1e-2 * std::max(1.0, std::sqrt(x0[1] * x0[1] + x0[2] * x0[2] + x0[3] * x0[3]));
  }

  // The visitor: sees each accepted step; true when the ray hit an object
  // (res filled).  Every object of the scene tests the step (the earliest
  // hit wins); a crossing of the equatorial plane before where the ray ends
  // counts towards hit.order (located only when a hit in the step makes its
  // order matter, or an object located it anyway).
  bool visit(const RayStep& step, RayResult& res) {
    const S& st = sc_.spacetime;
    on_step_(step.start(), step.t0);
    StepTest t(step, out_.reuse_window, track_windows_, warm_);
    std::size_t winner = no_object;
    for_each_object(sc_.objects, [&](const auto& o, std::size_t index) {
      if (const auto l = o.first_hit(st, t, index)) {
        t.take(*l);
        winner = index;
      }
    });
    if (t.crosses_equator()) {
      const double lz = t.found() || t.equator_located() ? t.equator_crossing() : step.t0;
      if (lz < t.best()) ++crossings_;
    }
    if (winner == no_object) return false;
    hit_object(step.at(t.best()), t.best(), winner, res);
    return true;
  }

  // The sample, once the integration has ended with `res`.
  // `sky` gets where a sky ray went (untouched otherwise).
  RayHit finish(const RayResult& res, SkyPoint& sky) {
    out_.steps = res.steps;
    out_.reason = res.reason;
    out_.end = res.y;
    out_.lambda_end = res.lambda;
    if (res.reason == StopReason::hit) return out_;
    const Vec4 x = {res.y[0], res.y[1], res.y[2], res.y[3]};
    double t, r, phi;
    scene_polar(sc_.spacetime, x, t, r, phi);
    out_.r = r;
    out_.phi = phi;
    out_.t = t - sc_.observer_time;
    out_.order = crossings_;
    if (res.reason == StopReason::horizon) {
      out_.kind = HitKind::horizon;
      return out_;
    }
    if (res.reason != StopReason::escaped) return out_;  // gave up: black, kind 4
    sky_sample(sc_, x, {res.y[4], res.y[5], res.y[6], res.y[7]}, out_, sky);
    out_.g = 1.0 / res.y[4];  // the source at rest far away: p.u = p_t
    // ... where it is its own ZAMO: g_grav = D(u_ref,obs) g.
    const SeenShift shift = sc_.light.seen(out_.g, observer_reference() * out_.g);
    out_.color = shift.texture(out_.color);
    sky.color = static_cast<float>(shift.color);
    sky.beaming = static_cast<float>(shift.beaming);
    return out_;
  }

 private:
  // nu_observed / nu_emitted for light that left the event y (its momentum
  // there) from matter of 4-velocity u.
  static double frequency_ratio(const RayState& y, const Vec4& u) {
    return 1.0 / (y[4] * u[0] + y[5] * u[1] + y[6] * u[2] + y[7] * u[3]);
  }
  // p.u_ref at the observer, where the light model splits g (light/light.hpp).
  double observer_reference() const {
    if (!sc_.light.splits()) return 1.0;
    const Vec4& u = sc_.reference_observer;
    return p0_[0] * u[0] + p0_[1] * u[1] + p0_[2] * u[2] + p0_[3] * u[3];
  }
  // How light of ratio g from the event y is seen.
  SeenShift seen(double g, const RayState& y) const {
    if (!sc_.light.splits()) return sc_.light.seen(g, g);
    return seen_in_parts(g, y);
  }
  // The same where g is split: g_grav = D(u_ref,obs) / D(u_ref,em), the
  // ZAMOs' at the two ends.  Kept out of line: the visitor is inlined into
  // every step of the integration.
  [[gnu::noinline]] SeenShift seen_in_parts(double g, const RayState& y) const {
    const Vec4 x = {y[0], y[1], y[2], y[3]};
    return sc_.light.seen(g, observer_reference() * frequency_ratio(y, zamo_velocity(sc_.spacetime, x)));
  }
  // Ends the ray at the event y (affine parameter lambda) on the object
  // numbered `winner`: its frequency ratio and colour.  Kept out of line:
  // it runs once per ray, while the visitor is inlined into every step of
  // the integration, where its size decides what else the compiler inlines.
  [[gnu::noinline]] void hit_object(const RayState& y, double lambda, std::size_t winner, RayResult& res) {
    const S& st = sc_.spacetime;
    for_each_object(sc_.objects, [&](const auto& o, std::size_t index) {
      if (index == winner) {
        const double g = frequency_ratio(y, o.emitter_velocity(st, y));
        hit(std::decay_t<decltype(o)>::hit_kind, o.color_at(st, y, seen(g, y)), g, y, lambda, res);
      }
    });
  }
  // Ends the ray at the event y (affine parameter lambda) on an object.
  bool hit(HitKind kind, const Color& color, double g, const RayState& y, double lambda, RayResult& res) {
    double t, r, phi;
    scene_polar(sc_.spacetime, {y[0], y[1], y[2], y[3]}, t, r, phi);
    out_.kind = kind;
    out_.color = color;
    out_.g = g;
    out_.r = r;
    out_.phi = phi;
    out_.t = t - sc_.observer_time;
    out_.order = crossings_;
    res.reason = StopReason::hit;
    res.y = y;
    res.lambda = lambda;
    return true;
  }

  const SceneIn<S>& sc_;
  OnStep& on_step_;
  Vec4 p0_;
  RayHit out_;
  int crossings_ = 0;
  bool track_windows_ = true;
  static constexpr std::size_t no_object = static_cast<std::size_t>(-1);
  ObjectWarmStarts warm_ = no_warm_starts();  // per object (the first few), carried along the ray
};

}  // namespace detail
}  // namespace lc
