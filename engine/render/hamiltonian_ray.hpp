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
#include "render/hit.hpp"
#include "render/scene.hpp"
#include "render/sphere_test.hpp"
#include "spacetime/chart.hpp"

namespace lc {

// For trace_sample: a path recorder that records nothing (rendering).
struct NoPath {
  void operator()(const RayState&, double) const {}
};

namespace detail {

// The sky seen by a ray that escaped at the trace-coordinate event x with
// momentum p: fills out.kind and out.color.
template <class S>
void sky_sample(const SceneOf<S>& sc, const Vec4& x, const Vec4& p, RaySample& out) {
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
}


// The general path: the Hamiltonian in the trace chart (Kerr–Schild for
// Kerr).  One ray's start, its visitor (spheres, the disk, plane crossings)
// and its result; run_rays (geodesic/ray_loop.hpp) integrates it, alone or
// beside others in vector lanes (render/trace.hpp).
template <class S, class OnStep>
class HamiltonianRay {
 public:
  HamiltonianRay(const SceneOf<S>& sc, const Vec3& n, OnStep& on_step)
      : sc_(sc), on_step_(on_step), p0_(backward_ray_momentum(sc.metric, sc.frame, n)) {}

  const Vec4& momentum() const { return p0_; }
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
  // (res filled).
  bool visit(const RayStep& step, RayResult& res) {
    const S& st = sc_.spacetime;
    on_step_(step.start(), step.t0);
    const double l1 = step.t0 + step.h;
    double best = l1 + 1.0;
    int hit_sphere = -1;
    std::optional<StepHull> hull;  // for the spheres the coarse boxes let through
    for (std::size_t k = 0; k < sc_.spheres.size(); ++k) {
      const Sphere& sphere = sc_.spheres[k];
      const SphereReach reach = detail::sphere_near_step(sphere, step);
      if (reach == SphereReach::never) continue;
      const bool timeless_yet = !out_.depends_on_time;
      if (reach == SphereReach::not_now && !timeless_yet) continue;
      if (!hull) hull = step_hull(step);
      // Near a moving sphere's path what the ray sees depends on where the
      // sphere is at the frame's time: no other frame may reuse it.  Near
      // one at rest too, though only to rounding: the sphere test works in
      // absolute coordinate time, so shifted in time its samples round
      // differently, and a grazing hit could flip.
      if (timeless_yet && hull_near_centres(*hull, sphere, sphere.life_lo, sphere.life_hi)) out_.depends_on_time = true;
      if (reach == SphereReach::not_now) continue;
      double none = std::numeric_limits<double>::quiet_NaN();
      double& t_near = k < sphere_times_.size() ? sphere_times_[k] : none;
      if (auto l = detail::sphere_entry(st, sphere, step, *hull, t_near); l && *l < best) {
        best = *l;
        hit_sphere = static_cast<int>(k);
      }
    }
    const double z0 = step.start()[3], z1 = step.component(3, l1);
    if ((z0 > 0.0) != (z1 > 0.0) && z0 != 0.0) {
      // Without a disk a crossing only counts (hit.order); it is located only
      // when a sphere hit in the same step makes its order matter.
      const double lz = sc_.disk || hit_sphere >= 0
                            ? locate_crossing(step, [](const RayState& y) { return y[3]; }, z0, z1)
                            : step.t0;
      if (!sc_.disk) {
        if (lz < best) ++crossings_;
      } else if (lz < best) {
        const RayState y = step.at(lz);
        double t, r, phi;
        scene_polar(st, {y[0], y[1], y[2], y[3]}, t, r, phi);
        if (r >= sc_.disk->spec.inner && r <= sc_.disk->spec.outer)
          return hit(HitKind::disk, sc_.disk->color(r, phi), y, lz, res);
        ++crossings_;
      }
    }
    if (hit_sphere >= 0) {
      const RayState y = step.at(best);
      const Sphere& sp = sc_.spheres[hit_sphere];
      return hit(HitKind::object, sp.color(detail::sphere_local(st, sp, {y[0], y[1], y[2], y[3]})), y, best, res);
    }
    return false;
  }

  // The sample, once the integration has ended with `res`.
  RaySample finish(const RayResult& res) {
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
    sky_sample(sc_, x, {res.y[4], res.y[5], res.y[6], res.y[7]}, out_);
    return out_;
  }

 private:
  // Ends the ray at the event y (affine parameter lambda) on an object.
  bool hit(HitKind kind, const Color& color, const RayState& y, double lambda, RayResult& res) {
    double t, r, phi;
    scene_polar(sc_.spacetime, {y[0], y[1], y[2], y[3]}, t, r, phi);
    out_.kind = kind;
    out_.color = color;
    out_.r = r;
    out_.phi = phi;
    out_.t = t - sc_.observer_time;
    out_.order = crossings_;
    res.reason = StopReason::hit;
    res.y = y;
    res.lambda = lambda;
    return true;
  }

  const SceneOf<S>& sc_;
  OnStep& on_step_;
  Vec4 p0_;
  RaySample out_;
  int crossings_ = 0;
  // Per sphere (the first few), the last simultaneity answer along this ray.
  std::array<double, 4> sphere_times_ = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
};

}  // namespace detail
}  // namespace lc
