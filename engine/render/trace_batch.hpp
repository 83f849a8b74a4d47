#pragma once
// Many camera rays of one scene at once: four per vector in lanes where the
// scene takes the Kerr BL–Mino path (geodesic/kerr_mino_lanes.hpp), one by
// one otherwise.  What the renderer calls for a row's samples.

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <type_traits>

#include "geodesic/kerr_mino_lanes.hpp"
#include "render/scene.hpp"

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
    const Lane4 e2 = dp5::error_sum(y, y7, k1, k3, k4, k5, k6, k7, hv, weights, opt.control);
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

}  // namespace detail

// Traces the camera rays of local directions `dirs` (on the observer's
// legs) into `out` (same size), as trace_sample does one by one.
template <class S>
void trace_batch(const SceneOf<S>& sc, std::span<const Vec3> dirs, std::span<RaySample> out) {
  if constexpr (std::is_same_v<S, Kerr>)
    if (sc.spheres.empty() && sc.rays.kerr_chart == KerrChart::boyer_lindquist_mino)
      return detail::trace_mino_lanes(sc, dirs, out);
  for (std::size_t k = 0; k < dirs.size(); ++k) out[k] = trace_sample(sc, dirs[k], NoPath{});
}

}  // namespace lc
