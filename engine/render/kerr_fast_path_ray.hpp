#pragma once
// One camera ray through a Kerr scene without spheres in the fast path
// (render/trace.hpp): the Boyer–Lindquist–Mino formulation (MinoPath,
// geodesic/kerr_mino.hpp, beside the integrator), with the visitor that finds disk hits,
// equatorial crossings, the escape and capture events and the direction at
// infinity, and fills the ray's hit record as the general path does.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "eye/ray_direction.hpp"
#include "geodesic/crossing.hpp"
#include "geodesic/kerr_mino.hpp"
#include "objects/objects.hpp"
#include "render/general_path_ray.hpp"
#include "render/hit_record.hpp"
#include "render/scene.hpp"

namespace lc::detail {

// The fast path looks for disks and nothing else: an object kind that says
// in_fast_path must be found in MinoRay::visit first.
template <class... O>
constexpr bool fast_path_kinds_are_disks(Registry<O...>*) {
  return ((O::in_fast_path == std::is_same_v<O, Disk>) && ...);
}
static_assert(fast_path_kinds_are_disks(static_cast<ObjectRegistry*>(nullptr)),
              "an object kind with in_fast_path = true must be looked for in MinoRay::visit");

// Where the fast path's rays are captured (0: nowhere, flat space).
inline double mino_capture_radius(const SceneIn<Kerr>& sc) {
  return sc.spacetime.mass() > 0.0 ? sc.spacetime.capture_radius() : 0.0;
}

// The Kerr fast path (geodesic/kerr_mino.hpp): Boyer–Lindquist and Mino
// time, for Kerr scenes without spheres.  The same results as the general
// path to the integration tolerance; the start, the end and what `lightcone
// trace` records are converted to Kerr–Schild.  One ray's start, its
// visitor (disk, escape, the layers' events) and its result; run_rays
// integrates it, alone or beside others in vector lanes (render/trace.hpp).
template <class OnStep>
class MinoRay {
 public:
  // observer_jacobian: Kerr–Schild over Boyer–Lindquist at the frame's eye
  // (trace_jacobian of sc.eye.scene_event), worked out once for a batch;
  // a ray from another eye works out its own.
  MinoRay(const SceneIn<Kerr>& sc, const Mat4& observer_jacobian, const RayStart& ray, OnStep& on_step)
      : sc_(sc), on_step_(on_step),
        start_(make_start(sc, *ray.eye,
                          ray.eye == &sc.eye ? observer_jacobian : sc.spacetime.trace_jacobian(ray.eye->scene_event),
                          ray.direction)),
        clock_(start_.k, start_.y0[1]), u_escape_(1.0 / sc.rays.escape_radius),
        u_capture_(capture_radius() > 0.0 ? 1.0 / capture_radius() : 1e300), at_escape_{start_.y0, start_.y0[0]},
        observer_reference_(observer_reference(sc, *ray.eye, ray.direction)) {
    if (ray.eye != &sc.eye) reuse_window_ = 0.0f;
  }

  // What run_rays starts the ray with.
  const KerrMinoConstants& constants() const { return start_.k; }
  MinoState start() const { return start_.y0; }
  MinoState slope() const { return start_.slope(); }
  double first_step() const { return start_.first_step(); }
  double capture_radius() const { return mino_capture_radius(sc_); }

  // The visitor: sees each accepted step; true when the ray hit the disk
  // (res filled).
  bool visit(const MinoStep& step, MinoResult& res) {
    const double u0 = step.start()[1];
    // The step ends at infinity if u reaches 0 in it; nothing beyond counts.
    double l1 = step.t0 + step.h, u1 = step.component(1, l1);
    if (u1 <= 0.0) {
      l1 = locate_crossing(step, [](const MinoState& y) { return y[1]; }, u0, u1);
      u1 = 0.0;
    }
    clock_.see(step, l1);
    if constexpr (!std::is_same_v<std::decay_t<OnStep>, NoPath>)
      on_step_(trace_state(event_at(step, step.t0)), step.start()[7]);
    const double c0 = step.start()[2], c1 = step.component(2, l1);
    if ((c0 > 0.0) != (c1 > 0.0) && c0 != 0.0) {
      const double lz = locate_crossing(step, [](const MinoState& y) { return y[2]; }, step.t0, l1, c0, c1);
      const Event e = event_at(step, lz);
      const std::vector<Disk>& disks = std::get<std::vector<Disk>>(sc_.objects->lists);
      const double r = disk_radius(e);
      for (std::size_t i = 0; i < disks.size(); ++i)
        if (disks[i].covers(r)) {
          disk_ = i;
          res.reason = StopReason::hit;
          res.y = e.y;
          res.lambda = lz;
          at_hit_ = e;
          return true;
        }
      if (e.y[1] > u_escape_) ++crossings_;  // as the Kerr–Schild path counts: up to the escape radius
    }
    if (u0 > u_escape_ && u1 <= u_escape_) {
      const double le = locate_crossing(
          step, [u = u_escape_](const MinoState& y) { return y[1] - u; }, step.t0, l1, u0 - u_escape_, u1 - u_escape_);
      at_escape_ = event_at(step, le);
    }
    if (u1 > u_capture_) {
      // The layers' event of a horizon pixel is on the capture surface, not
      // wherever the step ended (for Schwarzschild, inside the horizon).
      const double lc = locate_crossing(
          step, [u = u_capture_](const MinoState& y) { return y[1] - u; }, u0 - u_capture_, u1 - u_capture_, 1e-12);
      at_capture_ = event_at(step, lc);
    }
    if (res.reason == StopReason::escaped) {
      // At infinity phi_shift vanishes: the Kerr–Schild direction is the BL
      // angular position (sin th < 0 included: the same point).
      const MinoState y = step.at(l1);
      direction_ = {y[3] * std::cos(y[4]), y[3] * std::sin(y[4]), y[2]};
    }
    return false;
  }

  // The ray's record, once the integration has ended with `res`.
  void finish(const MinoResult& res, HitRecord& out) {
    out = HitRecord{};
    out.reuse_window = reuse_window_;
    out.steps = res.steps;
    out.reason = res.reason;
    const Event last = res.reason == StopReason::escaped   ? at_escape_
                       : res.reason == StopReason::horizon ? at_capture_
                       : res.reason == StopReason::hit     ? at_hit_
                                                           : Event{res.y, clock_.time(res.y, res.lambda)};
    // The end in trace coordinates costs a Jacobian, its inverse and two
    // logarithms: only `lightcone trace` (a path recorder) reads it.
    if constexpr (!std::is_same_v<std::decay_t<OnStep>, NoPath>) {
      out.end = trace_state(last);
      out.lambda_end = last.y[7];
    }
    fill_event(last, out);
    if (res.reason == StopReason::hit) {
      // The disk through the object seam: its kind, index and surface point.
      out.kind = Disk::hit_kind;
      out.object = static_cast<std::uint32_t>(object_index<Disk>(sc_.objects->lists, disk_));
      out.g = disk_frequency_ratio(at_hit_);
      out.g_gravity = disk_gravity_part(at_hit_, out.g);
      out.surface = {out.r, out.phi};
      return;
    }
    if (res.reason == StopReason::horizon) {
      out.kind = HitKind::horizon;
      out.spacetime_end = static_cast<std::uint8_t>(end_index<Kerr>(EndKind::horizon));
      return;
    }
    if (res.reason != StopReason::escaped) return;  // gave up: black, kind 4
    out.kind = HitKind::sky;
    out.spacetime_end = 0;  // Kerr's one infinity: u = 1/r reached 0
    const double n2 = norm3(direction_);
    out.sky_theta = std::acos(std::clamp(direction_[2] / n2, -1.0, 1.0));
    double sphi = std::atan2(direction_[1], direction_[0]);
    if (sphi < 0) sphi += two_pi;
    out.sky_phi = sphi;
    out.g = -1.0 / start_.k.E;  // the source at rest far away: p.u = p_t = -E
    // ... where it is its own ZAMO: g_grav = D(u_ref,obs) g.
    out.g_gravity = observer_reference_ * out.g;
  }

 private:
  // A point of the ray and its Boyer–Lindquist coordinate time (the state
  // holds tau, see kerr_mino.hpp).
  struct Event {
    MinoState y;
    double t;
  };
  // The event at Mino time lambda of the step the clock saw last.
  Event event_at(const MinoStep& step, double lambda) const {
    const MinoState y = step.at(lambda);
    return {y, clock_.time(y, lambda)};
  }

  static KerrMinoStart make_start(const SceneIn<Kerr>& sc, const Eye& eye, const Mat4& observer_jacobian,
                                  const Vec3& n) {
    const Kerr& st = sc.spacetime;
    const Vec4 p_ks = backward_ray_momentum(eye.metric, eye.frame, n);
    auto bl_momentum = [&](const Vec4& s) {
      const Mat4 J = st.trace_jacobian(s);
      Vec4 p{};
      for (int nu = 0; nu < 4; ++nu)
        for (int mu = 0; mu < 4; ++mu) p[nu] += p_ks[mu] * J[mu][nu];
      return p;
    };
    Vec4 s0 = eye.scene_event;
    Vec4 p_bl{};
    for (int nu = 0; nu < 4; ++nu)
      for (int mu = 0; mu < 4; ++mu) p_bl[nu] += p_ks[mu] * observer_jacobian[mu][nu];
    if (std::abs(std::sin(s0[2])) < spin_axis_sine) {
      // On the axis every phi names the observer's point, and the ray leaves it
      // along one meridian: p_theta at phi is A cos(phi) + B sin(phi) from the
      // meridians phi = 0 and pi/2, largest (the ray's own) at atan2(B, A).
      // (At theta = pi that sends theta beyond pi: sin theta < 0 stands for
      // the same point, see kerr_mino.hpp.)
      const Vec4 pa = bl_momentum({s0[0], s0[1], s0[2], 0.0});
      const Vec4 pb = bl_momentum({s0[0], s0[1], s0[2], 0.5 * pi});
      s0[3] = std::atan2(pb[2], pa[2]);
      p_bl[2] = std::hypot(pa[2], pb[2]);
      p_bl[3] = 0.0;
    }
    return kerr_mino_start(st.mass(), st.spin(), st.charge(), s0, p_bl, sc.rays.escape_radius);
  }
  // An event as a trace-coordinate state (x^mu, p_mu), for the path
  // recorder and the layers' end event.
  RayState trace_state(const Event& e) const {
    const Kerr& st = sc_.spacetime;
    Vec4 s, p;
    kerr_mino_event(start_.k, e.y, s, p);
    s[0] = e.t;
    // On the spin axis the Boyer–Lindquist chart is singular (its Jacobian
    // has no inverse); a point 1e-12 rad off it is the same to rounding.
    if (std::abs(std::sin(s[2])) < 1e-12) s[2] = s[2] < 0.5 * pi ? 1e-12 : pi - 1e-12;
    const Mat4 Ji = inverse(st.trace_jacobian(s));
    const Vec4 x = st.trace_from_scene(s);
    Vec4 pk{};
    for (int mu = 0; mu < 4; ++mu)
      for (int nu = 0; nu < 4; ++nu) pk[mu] += p[nu] * Ji[nu][mu];
    return RayState{x[0], x[1], x[2], x[3], pk[0], pk[1], pk[2], pk[3]};
  }
  // p.u_ref at the eye, where the light model splits g (light/light.hpp).
  static double observer_reference(const SceneIn<Kerr>& sc, const Eye& eye, const Vec3& n) {
    if (!sc.light.splits()) return 1.0;
    const Vec4 p = backward_ray_momentum(eye.metric, eye.frame, n);
    const Vec4& u = eye.reference;
    return p[0] * u[0] + p[1] * u[1] + p[2] * u[2] + p[3] * u[3];
  }
  // The gravitational part of the ratio g of light from the disk at e where
  // the light model splits g: D(u_ref,obs) / D(u_ref,em), the ZAMO at e in
  // Boyer–Lindquist, u^mu = -g^{mu t} / sqrt(-g^{tt}); g where it does not.
  double disk_gravity_part(const Event& e, double g) const {
    if (!sc_.light.splits()) return g;
    Vec4 s, p;
    kerr_mino_event(start_.k, e.y, s, p);
    const Mat4 m = sc_.spacetime.bl_metric(s);
    const double det = m[0][0] * m[3][3] - m[0][3] * m[0][3];
    const double gtt = m[3][3] / det, gtp = -m[0][3] / det;
    const double d_ref = -(p[0] * gtt + p[3] * gtp) / std::sqrt(-gtt);
    return observer_reference_ / d_ref;
  }
  // Boyer–Lindquist r at the event e (where the disk is looked for).
  double disk_radius(const Event& e) const {
    Vec4 s, p;
    kerr_mino_event(start_.k, e.y, s, p);
    return s[1];
  }
  // nu_observed / nu_emitted for light that left the disk at e: 1 / (p_mu
  // u^mu) in Boyer–Lindquist, the matter's u from Kerr::disk_velocity_bl.
  double disk_frequency_ratio(const Event& e) const {
    Vec4 s, p;
    kerr_mino_event(start_.k, e.y, s, p);
    const Vec4 u = sc_.spacetime.disk_velocity_bl(s[1]);
    return 1.0 / (p[0] * u[0] + p[1] * u[1] + p[3] * u[3]);
  }
  void fill_event(const Event& e, HitRecord& out) const {
    Vec4 s, p;
    kerr_mino_event(start_.k, e.y, s, p);
    out.r = s[1];
    out.phi = s[3];
    out.t = e.t - sc_.eye.time;
    out.order = crossings_;
  }

  const SceneIn<Kerr>& sc_;
  OnStep& on_step_;
  KerrMinoStart start_;
  MinoClock clock_;
  double u_escape_;
  double u_capture_;  // 1 / capture radius (1e300: nothing is captured)
  Event at_escape_;   // where r passed the escape radius (the layers' end event)
  Event at_capture_{};  // where r passed the capture radius (the same for the horizon)
  Event at_hit_{};      // where the ray met the disk
  Vec3 direction_{};  // at infinity, in the Kerr–Schild Cartesian frame
  double observer_reference_;  // p.u_ref at the eye (1 where g is not split)
  float reuse_window_ = std::numeric_limits<float>::infinity();  // HitRecord::reuse_window (no moving objects here)
  int crossings_ = 0;
  std::size_t disk_ = 0;  // which disk the ray hit (its index in the disks' list)
};

}  // namespace lc::detail
