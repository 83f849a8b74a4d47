#pragma once
// One camera ray through a scene in the general path (render/trace.hpp):
// the Hamiltonian formulation (HamiltonianPath, geodesic/null_ray.hpp,
// beside the integrator) in the spacetime's trace chart, with the visitor that
// tests each step against the scene's objects, counts equatorial crossings
// (hit.order) and, at the end, fills the ray's hit record
// (render/hit_record.hpp): the object met and where, the sky direction or
// the horizon.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "eye/ray_direction.hpp"
#include "eye/tetrad.hpp"
#include "geodesic/crossing.hpp"
#include "objects/objects.hpp"
#include "render/hit_record.hpp"
#include "render/ray_start.hpp"
#include "render/scene.hpp"
#include "spacetime/chart.hpp"
#include "spacetime/weak_field_tail.hpp"

namespace lc {

// For trace_sample: a path recorder that records nothing (rendering).
struct NoPath {
  void operator()(const RayState&, double) const {}
};

namespace detail {

// The direction at infinity (theta from +z, phi in [0, 2 pi)) of a ray that
// escaped at the trace-coordinate event x with momentum p: the spatial
// tangent, bent by the deflection still to come between here and infinity
// (the spacetime's far field).
template <class S>
void sky_direction(const S& st, const Vec4& x, const Vec4& p, double& theta, double& phi) {
  Vec4 dx, dp;
  st.hamiltonian_rhs(x, p, dx, dp);
  Vec3 d = {dx[1], dx[2], dx[3]};
  const double dn = norm3(d);
  for (auto& c : d) c /= dn;
  d = st.escape_direction(x, d);
  theta = std::acos(std::clamp(d[2], -1.0, 1.0));
  phi = std::atan2(d[1], d[0]);
  if (phi < 0) phi += two_pi;
}


// The general path: the Hamiltonian in the trace chart (Kerr–Schild for
// Kerr).  One ray's start, its visitor (spheres, the disk, plane crossings)
// and its result; run_rays (geodesic/ray_loop.hpp) integrates it, alone or
// beside others in vector lanes (render/trace.hpp).
template <class S, class OnStep>
class HamiltonianRay {
 public:
  HamiltonianRay(const SceneIn<S>& sc, const RayStart& start, OnStep& on_step)
      : sc_(sc), eye_(*start.eye), on_step_(on_step),
        p0_(backward_ray_momentum(eye_.metric, eye_.frame, start.direction)) {
    // No other frame can reuse a ray of a frame without a still key, nor
    // one from an eye of its own.
    if (sc.still_key.empty() || start.eye != &sc.eye) reuse_window_ = 0.0f;
  }

  const Vec4& momentum() const { return p0_; }
  // Whether the objects work out for how long another frame could reuse
  // the ray (HitRecord::reuse_window); if not, a ray that comes near a moving
  // object's path gets 0 at once and the others stay unlimited.
  void track_reuse_windows(bool track) { track_windows_ = track && track_windows_; }
  // What run_rays starts the ray with.
  RayState start() const {
    const Vec4& x0 = eye_.event;
    return {x0[0], x0[1], x0[2], x0[3], p0_[0], p0_[1], p0_[2], p0_[3]};
  }
  RayState slope() const {
    RayState dy;
    sc_.spacetime.rhs(start(), dy);
    return dy;
  }
  double first_step() const {
    const Vec4& x0 = eye_.event;
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
    StepTest t(step, reuse_window_, track_windows_, warm_);
    std::size_t winner = no_object;
    for_each_object(sc_.objects->lists, [&](const auto& o, std::size_t index) {
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
    winner_ = winner;
    res.reason = StopReason::hit;
    res.y = step.at(t.best());
    res.lambda = t.best();
    return true;
  }

  // The ray's record, once the integration has ended with `res`.
  void finish(const RayResult& res, HitRecord& out) {
    out = HitRecord{};
    out.reuse_window = reuse_window_;
    out.steps = res.steps;
    out.reason = res.reason;
    out.end = res.y;
    out.lambda_end = res.lambda;
    if (res.reason == StopReason::hit) return hit_object(res.y, out);
    const Vec4 x = {res.y[0], res.y[1], res.y[2], res.y[3]};
    fill_event(x, out);
    if (res.reason == StopReason::horizon) {
      out.kind = HitKind::horizon;
      out.spacetime_end = horizon_end;
      return;
    }
    if (res.reason != StopReason::escaped) return;  // gave up: black, kind 4
    out.kind = HitKind::sky;
    out.spacetime_end = res.end;
    sky_direction(sc_.spacetime, x, {res.y[4], res.y[5], res.y[6], res.y[7]}, out.sky_theta, out.sky_phi);
    // The source at rest at that end: p.u = p_t / its lapse there.
    out.g = sc_.spacetime.sky_source_lapse(res.end) / res.y[4];
    // ... where it is its own ZAMO: g_grav = D(u_ref,obs) g.
    out.g_gravity = observer_reference() * out.g;
  }

 private:
  // nu_observed / nu_emitted for light that left the event y (its momentum
  // there) from matter of 4-velocity u.
  static double frequency_ratio(const RayState& y, const Vec4& u) {
    return 1.0 / (y[4] * u[0] + y[5] * u[1] + y[6] * u[2] + y[7] * u[3]);
  }
  // p.u_ref at the eye, where the light model splits g (light/light.hpp).
  double observer_reference() const {
    if (!sc_.light.splits()) return 1.0;
    const Vec4& u = eye_.reference;
    return p0_[0] * u[0] + p0_[1] * u[1] + p0_[2] * u[2] + p0_[3] * u[3];
  }
  // The gravitational part of the ratio g of light from the event y where
  // the light model splits g: D(u_ref,obs) / D(u_ref,em), the ZAMOs' at the
  // two ends; g itself where it does not.
  double gravity_part(double g, const RayState& y) const {
    if (!sc_.light.splits()) return g;
    const Vec4 x = {y[0], y[1], y[2], y[3]};
    return observer_reference() * frequency_ratio(y, zamo_velocity(sc_.spacetime, x));
  }
  // The end event's scene time (minus the frame's), r and phi, and the
  // crossings before it.
  void fill_event(const Vec4& x, HitRecord& out) const {
    double t, r, phi;
    scene_polar(sc_.spacetime, x, t, r, phi);
    out.r = r;
    out.phi = phi;
    out.t = t - sc_.eye.time;
    out.order = crossings_;
  }
  // The record of a hit at the event y on the object numbered winner_: the
  // frequency ratio, where on the object.  Kept out of line: it runs once
  // per ray, while the visitor is inlined into every step of the
  // integration, where its size decides what else the compiler inlines.
  [[gnu::noinline]] void hit_object(const RayState& y, HitRecord& out) const {
    const S& st = sc_.spacetime;
    for_each_object(sc_.objects->lists, [&](const auto& o, std::size_t index) {
      if (index == winner_) {
        out.kind = std::decay_t<decltype(o)>::hit_kind;
        out.object = static_cast<std::uint32_t>(index);
        out.g = frequency_ratio(y, o.emitter_velocity(st, y));
        out.g_gravity = gravity_part(out.g, y);
        out.surface = o.surface_at(st, y);
      }
    });
    fill_event({y[0], y[1], y[2], y[3]}, out);
  }

  const SceneIn<S>& sc_;
  const Eye& eye_;
  OnStep& on_step_;
  Vec4 p0_;
  float reuse_window_ = std::numeric_limits<float>::infinity();  // HitRecord::reuse_window, as the steps narrow it
  int crossings_ = 0;
  std::size_t winner_ = no_object;  // the object hit
  bool track_windows_ = true;
  static constexpr std::size_t no_object = static_cast<std::size_t>(-1);
  static constexpr auto horizon_end = static_cast<std::uint8_t>(end_index<S>(EndKind::horizon));
  ObjectWarmStarts warm_ = no_warm_starts();  // per object (the first few), carried along the ray
};

}  // namespace detail
}  // namespace lc
