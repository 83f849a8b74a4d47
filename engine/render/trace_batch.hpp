#pragma once
// Many camera rays of one scene at once: four per vector in lanes for the
// Kerr BL–Mino path (geodesic/kerr_mino_lanes.hpp) and the dihole
// (spacetime/dihole_lanes.hpp), one by one otherwise (flat space, Kerr with
// spheres).  What the renderer and the bench call for a row's samples.

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <type_traits>

#include "geodesic/kerr_mino_lanes.hpp"
#include "render/scene.hpp"
#include "spacetime/dihole_lanes.hpp"

namespace lc {

namespace detail {

// Integrates the rays of `dirs` four at a time: each lane has its own ray
// (its MinoRay visitor), step size and controller, and the same stopping
// rules as trace_kerr_mino; a lane whose ray ends takes the next one.
// Assumes sc takes the BL–Mino path.  Results agree with trace_sample to
// the last bits (the compiler may contract vector and scalar arithmetic
// differently).
inline void trace_mino_lanes(const SceneOf<Kerr>& sc, std::span<const Vec3> dirs, std::span<RaySample> out) {
  const RayOptions& opt = sc.rays;
  const std::array<double, 8> weights = {0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0};  // as trace_kerr_mino
  NoPath no_path;
  struct Lane {
    std::optional<MinoRay<NoPath>> ray;
    std::size_t index = 0;
    MinoResult res;
    dp5::Controller control;
    double t = 0, h = 0, u_capture = 1e300;
    bool live = false;
  };
  std::array<Lane, lane_count> lanes;
  KerrMinoRhs4 rhs;  // idle lanes keep finite constants (zeros, or their last ray's)
  MinoLanes y{}, k1{};
  const MinoState idle = {0, 0.01, 0, 1, 0, 0, 0, 0};  // a state with a finite right-hand side
  std::size_t next = 0;
  auto put = [&](MinoLanes& v, int i, const MinoState& s) {
    for (int j = 0; j < 8; ++j) v[j][i] = s[j];
  };
  auto take = [&](const MinoLanes& v, int i) {
    MinoState s;
    for (int j = 0; j < 8; ++j) s[j] = v[j][i];
    return s;
  };
  auto load = [&](int i) {
    Lane& l = lanes[i];
    if (next >= dirs.size()) {
      l.live = false;
      l.ray.reset();
      put(y, i, idle);
      put(k1, i, MinoState{});
      return;
    }
    l.index = next++;
    l.ray.emplace(sc, dirs[l.index], no_path);
    const KerrMinoStart& st = l.ray->start();
    rhs.set(i, st.rhs);
    put(y, i, st.y0);
    MinoState k;
    st.rhs(0.0, st.y0, k);
    put(k1, i, k);
    l.res = MinoResult{};
    l.control.reset();
    l.t = 0.0;
    l.h = 1e-2 * std::min(1.0, st.y0[1]);  // as trace_kerr_mino
    const double cr = l.ray->capture_radius();
    l.u_capture = cr > 0.0 ? 1.0 / cr : 1e300;
    l.live = true;
  };
  auto end_ray = [&](int i) {
    Lane& l = lanes[i];
    out[l.index] = l.ray->finish(l.res);
    load(i);
  };
  for (int i = 0; i < lane_count; ++i) load(i);

  MinoLanes y7, k3, k4, k5, k6, k7, r1, r2, r3, r4, r5;
  MinoStep step;
  const Lane4 atol = Lane4{} + opt.control.atol, rtol = Lane4{} + opt.control.rtol;
  for (;;) {
    bool any = false;
    Lane4 tv{}, hv{};
    for (int i = 0; i < lane_count; ++i) {
      any = any || lanes[i].live;
      tv[i] = lanes[i].t;
      hv[i] = lanes[i].live ? lanes[i].h : 0.0;
    }
    if (!any) break;
    dp5::stages(rhs, tv, y, k1, hv, y7, k3, k4, k5, k6, k7);
    const Lane4 e2 = dp5::error_sum(y, y7, k1, k3, k4, k5, k6, k7, hv, weights, atol, rtol);
    dp5::dense_coefficients(y, y7, k1, k3, k4, k5, k6, k7, hv, r1, r2, r3, r4, r5);
    for (int i = 0; i < lane_count; ++i) {
      Lane& l = lanes[i];
      if (!l.live) continue;
      const double h = l.h;
      if (std::abs(h) < opt.control.h_min) {
        l.res.reason = StopReason::gave_up;
        l.res.y = take(y, i);
        l.res.lambda = l.t;
        end_ray(i);
        continue;
      }
      double h_next = h;
      if (!l.control.decide(std::sqrt(e2[i] / 8.0), h, opt.control, h_next)) {
        l.h = h_next;
        continue;
      }
      step.t0 = l.t;
      step.h = h;
      for (int j = 0; j < 8; ++j) {
        step.r1[j] = r1[j][i];
        step.r2[j] = r2[j][i];
        step.r3[j] = r3[j][i];
        step.r4[j] = r4[j][i];
        step.r5[j] = r5[j][i];
        y[j][i] = y7[j][i];
        k1[j][i] = k7[j][i];
      }
      l.t += h;
      l.h = h_next;
      ++l.res.steps;
      const double u = y[1][i];
      if (u <= 0.0) l.res.reason = StopReason::escaped;  // the visitor sees the step that reaches infinity
      if (l.ray->visit(step, l.res)) {
        end_ray(i);
        continue;
      }
      bool done = l.res.reason == StopReason::escaped;
      if (!done && u > l.u_capture) {
        l.res.reason = StopReason::horizon;
        done = true;
      }
      if (!done && l.res.steps >= opt.max_steps) {
        l.res.reason = StopReason::step_limit;
        done = true;
      }
      if (done) {
        l.res.y = take(y, i);
        l.res.lambda = l.t;
        end_ray(i);
      }
    }
  }
}

// The general Hamiltonian path four rays at a time (Rhs4: the spacetime's
// right-hand side on lanes), with the stopping rules of trace_null_ray and
// a HamiltonianRay visitor per lane; each lane has its own step size,
// controller and tolerances (relaxed in free flight).
template <class S, class Rhs4>
void trace_hamiltonian_lanes(const SceneOf<S>& sc, const Rhs4& rhs, std::span<const Vec3> dirs,
                             std::span<RaySample> out) {
  const S& st = sc.spacetime;
  const RayOptions& opt = sc.rays;
  const std::array<double, 8> weights = {0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0};  // as trace_null_ray
  const double R2 = opt.escape_radius * opt.escape_radius;
  const double free2 = opt.free_radius > 0.0 ? opt.free_radius * opt.free_radius : 1e300;
  NoPath no_path;
  struct Lane {
    std::optional<HamiltonianRay<S, NoPath>> ray;
    std::size_t index = 0;
    RayResult res;
    dp5::Controller control;
    double t = 0, h = 0;
    bool live = false, relaxed = false;
  };
  std::array<Lane, lane_count> lanes;
  RayLanes y{}, k1{};
  Lane4 atol = Lane4{} + opt.control.atol, rtol = Lane4{} + opt.control.rtol;
  // An idle lane's state: far out, moving on; its right-hand side is finite.
  const RayState idle = {0, 0, 1e3, 0, 1, 0, 1, 0};
  auto scalar_rhs = [&](const RayState& yy, RayState& dy) {
    Vec4 dx, dp;
    st.hamiltonian_rhs({yy[0], yy[1], yy[2], yy[3]}, {yy[4], yy[5], yy[6], yy[7]}, dx, dp);
    dy = {dx[0], dx[1], dx[2], dx[3], dp[0], dp[1], dp[2], dp[3]};
  };
  std::size_t next = 0;
  auto put = [&](RayLanes& v, int i, const RayState& s) {
    for (int j = 0; j < 8; ++j) v[j][i] = s[j];
  };
  auto take = [&](const RayLanes& v, int i) {
    RayState s;
    for (int j = 0; j < 8; ++j) s[j] = v[j][i];
    return s;
  };
  auto load = [&](int i) {
    Lane& l = lanes[i];
    atol[i] = opt.control.atol;
    rtol[i] = opt.control.rtol;
    if (next >= dirs.size()) {
      l.live = false;
      l.ray.reset();
      RayState k;
      scalar_rhs(idle, k);
      put(y, i, idle);
      put(k1, i, k);
      return;
    }
    l.index = next++;
    l.ray.emplace(sc, dirs[l.index], no_path);
    const Vec4& x0 = sc.observer;
    const Vec4& p0 = l.ray->momentum();
    const RayState y0 = {x0[0], x0[1], x0[2], x0[3], p0[0], p0[1], p0[2], p0[3]};
    RayState k;
    scalar_rhs(y0, k);
    put(y, i, y0);
    put(k1, i, k);
    l.res = RayResult{};
    l.control.reset();
    l.t = 0.0;
    l.h = 1e-2 * std::max(1.0, std::sqrt(x0[1] * x0[1] + x0[2] * x0[2] + x0[3] * x0[3]));  // as trace_null_ray
    l.relaxed = false;
    l.live = true;
  };
  auto end_ray = [&](int i) {
    Lane& l = lanes[i];
    out[l.index] = l.ray->finish(l.res);
    load(i);
  };
  for (int i = 0; i < lane_count; ++i) load(i);

  RayLanes y7, k3, k4, k5, k6, k7, r1, r2, r3, r4, r5;
  RayStep step;
  for (;;) {
    bool any = false;
    Lane4 tv{}, hv{};
    for (int i = 0; i < lane_count; ++i) {
      any = any || lanes[i].live;
      tv[i] = lanes[i].t;
      hv[i] = lanes[i].live ? lanes[i].h : 0.0;
    }
    if (!any) break;
    dp5::stages(rhs, tv, y, k1, hv, y7, k3, k4, k5, k6, k7);
    const Lane4 e2 = dp5::error_sum(y, y7, k1, k3, k4, k5, k6, k7, hv, weights, atol, rtol);
    dp5::dense_coefficients(y, y7, k1, k3, k4, k5, k6, k7, hv, r1, r2, r3, r4, r5);
    for (int i = 0; i < lane_count; ++i) {
      Lane& l = lanes[i];
      if (!l.live) continue;
      const double h = l.h;
      if (std::abs(h) < opt.control.h_min) {
        l.res.reason = StopReason::gave_up;
        l.res.y = take(y, i);
        l.res.lambda = l.t;
        end_ray(i);
        continue;
      }
      StepControl c = opt.control;
      c.atol = atol[i];
      c.rtol = rtol[i];
      double h_next = h;
      if (!l.control.decide(std::sqrt(e2[i] / 8.0), h, c, h_next)) {
        l.h = h_next;
        continue;
      }
      step.t0 = l.t;
      step.h = h;
      for (int j = 0; j < 8; ++j) {
        step.r1[j] = r1[j][i];
        step.r2[j] = r2[j][i];
        step.r3[j] = r3[j][i];
        step.r4[j] = r4[j][i];
        step.r5[j] = r5[j][i];
        y[j][i] = y7[j][i];
        k1[j][i] = k7[j][i];
      }
      l.t += h;
      l.h = h_next;
      ++l.res.steps;
      if (l.ray->visit(step, l.res)) {
        end_ray(i);
        continue;
      }
      const RayState yi = take(y, i);
      bool done = false;
      if (st.captured({yi[0], yi[1], yi[2], yi[3]})) {
        l.res.reason = StopReason::horizon;
        done = true;
      } else {
        const double rho2 = yi[1] * yi[1] + yi[2] * yi[2] + yi[3] * yi[3];
        const bool outward = yi[1] * k1[1][i] + yi[2] * k1[2][i] + yi[3] * k1[3][i] > 0.0;
        if (!l.relaxed && rho2 > free2 && outward) {
          atol[i] *= free_flight_relaxation;
          rtol[i] *= free_flight_relaxation;
          l.relaxed = true;
        }
        if (rho2 > R2 && outward) {
          l.res.reason = StopReason::escaped;
          done = true;
        } else if (l.res.steps >= opt.max_steps) {
          l.res.reason = StopReason::step_limit;
          done = true;
        }
      }
      if (done) {
        l.res.y = yi;
        l.res.lambda = l.t;
        end_ray(i);
      }
    }
  }
}

}  // namespace detail

// Traces the camera rays of local directions `dirs` (on the observer's
// legs) into `out` (same size), as trace_sample does one by one.
template <class S>
void trace_batch(const SceneOf<S>& sc, std::span<const Vec3> dirs, std::span<RaySample> out) {
  if constexpr (std::is_same_v<S, Kerr>) {
    if (sc.spheres.empty() && sc.rays.kerr_chart == KerrChart::boyer_lindquist_mino)
      return detail::trace_mino_lanes(sc, dirs, out);
  } else if constexpr (std::is_same_v<S, Dihole>) {
    return detail::trace_hamiltonian_lanes(sc, DiholeRhs4(sc.spacetime), dirs, out);
  }
  for (std::size_t k = 0; k < dirs.size(); ++k) out[k] = trace_sample(sc, dirs[k], NoPath{});
}

}  // namespace lc
