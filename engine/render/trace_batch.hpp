#pragma once
// Many camera rays of one scene at once: one per vector lane (four or eight,
// geodesic/lanes.hpp) for the
// Kerr BL–Mino path (geodesic/kerr_mino_lanes.hpp) and the dihole
// (spacetime/dihole_lanes.hpp), one by one otherwise (flat space, Kerr with
// spheres).  What the renderer and the bench call for a row's samples.

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>

#include "geodesic/dormand_prince_lanes.hpp"
#include "geodesic/kerr_mino_lanes.hpp"
#include "render/scene.hpp"
#include "spacetime/dihole_lanes.hpp"

namespace lc {

namespace detail {

// Ends lane i's ray: its state and parameter from the integrator unless the
// visitor set them (a hit), then its sample into `out`.  For both lane
// drivers below.
template <class Lane, class Integrator>
void finish_lane(Lane& l, const Integrator& dp, int i, bool set_end, std::span<RaySample> out) {
  if (set_end) {
    l.res.y = dp.y(i);
    l.res.lambda = dp.t(i);
  }
  out[l.index] = l.ray->finish(l.res);
}

// Integrates the rays of `dirs` lane_count at a time: each lane has its own ray
// (its MinoRay visitor), step size and controller, and the same stopping
// rules as trace_kerr_mino; a lane whose ray ends takes the next one.
// Assumes sc takes the BL–Mino path.  Results agree with trace_sample to
// the last bits (the compiler may contract vector and scalar arithmetic
// differently).
inline void trace_mino_lanes(const SceneOf<Kerr>& sc, std::span<const Vec3> dirs, std::span<RaySample> out) {
  const RayOptions& opt = sc.rays;
  NoPath no_path;
  struct Lane {
    std::optional<MinoRay<NoPath>> ray;
    std::size_t index = 0;
    MinoResult res;
    double u_capture = 1e300;
  };
  std::array<Lane, lane_count> lanes;
  KerrMinoRhs4 rhs;  // idle lanes keep finite constants (zeros, or their last ray's)
  // Weights as trace_kerr_mino's: t and sigma do not steer the step.
  DormandPrince5Lanes<KerrMinoRhs4> dp(rhs, opt.control, {0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0});
  const MinoState idle = {0, 0.01, 0, 1, 0, 0, 0, 0};  // a state with a finite right-hand side
  std::size_t next = 0;
  auto load = [&](int i) {
    Lane& l = lanes[i];
    if (next >= dirs.size()) {
      l.ray.reset();
      dp.stop(i, idle, MinoState{});
      return;
    }
    l.index = next++;
    l.ray.emplace(sc, dirs[l.index], no_path);
    const KerrMinoStart& st = l.ray->start();
    rhs.set(i, st.rhs);
    MinoState k;
    st.rhs(0.0, st.y0, k);
    dp.start(i, st.y0, k, 1e-2 * std::min(1.0, st.y0[1]));  // the first step of trace_kerr_mino
    l.res = MinoResult{};
    const double cr = l.ray->capture_radius();
    l.u_capture = cr > 0.0 ? 1.0 / cr : 1e300;
  };
  auto end_ray = [&](int i, bool set_end) {
    finish_lane(lanes[i], dp, i, set_end, out);
    load(i);
  };
  for (int i = 0; i < lane_count; ++i) load(i);
  auto accepted = [&](int i, const MinoStep& step) {
    Lane& l = lanes[i];
    ++l.res.steps;
    const double u = dp.y(i, 1);
    if (u <= 0.0) l.res.reason = StopReason::escaped;  // the visitor sees the step that reaches infinity
    if (l.ray->visit(step, l.res)) return end_ray(i, false);
    if (l.res.reason == StopReason::escaped) return end_ray(i, true);
    if (u > l.u_capture) {
      l.res.reason = StopReason::horizon;
      return end_ray(i, true);
    }
    if (l.res.steps >= opt.max_steps) {
      l.res.reason = StopReason::step_limit;
      end_ray(i, true);
    }
  };
  auto gave_up = [&](int i) {
    lanes[i].res.reason = StopReason::gave_up;
    end_ray(i, true);
  };
  while (dp.attempt(accepted, gave_up)) {
  }
}

// The general Hamiltonian path lane_count rays at a time (Rhs4: the spacetime's
// right-hand side on lanes), with the stopping rules of trace_null_ray and
// a HamiltonianRay visitor per lane; each lane has its own step size,
// controller and tolerances (relaxed in free flight).
template <class S, class Rhs4>
void trace_hamiltonian_lanes(const SceneOf<S>& sc, const Rhs4& rhs, std::span<const Vec3> dirs,
                             std::span<RaySample> out) {
  const S& st = sc.spacetime;
  const RayOptions& opt = sc.rays;
  const double R2 = opt.escape_radius * opt.escape_radius;
  const double free2 = opt.free_radius > 0.0 ? opt.free_radius * opt.free_radius : 1e300;
  NoPath no_path;
  struct Lane {
    std::optional<HamiltonianRay<S, NoPath>> ray;
    std::size_t index = 0;
    RayResult res;
    bool relaxed = false;
  };
  std::array<Lane, lane_count> lanes;
  // Weights as trace_null_ray's: t and p_t do not steer the step.
  DormandPrince5Lanes<Rhs4> dp(rhs, opt.control, {0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0});
  // An idle lane's state: far out, moving on; its right-hand side is finite.
  const RayState idle = {0, 0, 1e3, 0, 1, 0, 1, 0};
  auto scalar_rhs = [&](const RayState& yy) {
    Vec4 dx, dp4;
    st.hamiltonian_rhs({yy[0], yy[1], yy[2], yy[3]}, {yy[4], yy[5], yy[6], yy[7]}, dx, dp4);
    return RayState{dx[0], dx[1], dx[2], dx[3], dp4[0], dp4[1], dp4[2], dp4[3]};
  };
  std::size_t next = 0;
  auto load = [&](int i) {
    Lane& l = lanes[i];
    if (next >= dirs.size()) {
      l.ray.reset();
      dp.stop(i, idle, scalar_rhs(idle));
      return;
    }
    l.index = next++;
    l.ray.emplace(sc, dirs[l.index], no_path);
    const Vec4& x0 = sc.observer;
    const Vec4& p0 = l.ray->momentum();
    const RayState y0 = {x0[0], x0[1], x0[2], x0[3], p0[0], p0[1], p0[2], p0[3]};
    // The first step of trace_null_ray.
    dp.start(i, y0, scalar_rhs(y0), 1e-2 * std::max(1.0, std::sqrt(x0[1] * x0[1] + x0[2] * x0[2] + x0[3] * x0[3])));
    l.res = RayResult{};
    l.relaxed = false;
  };
  auto end_ray = [&](int i, bool set_end) {
    finish_lane(lanes[i], dp, i, set_end, out);
    load(i);
  };
  for (int i = 0; i < lane_count; ++i) load(i);
  auto accepted = [&](int i, const RayStep& step) {
    Lane& l = lanes[i];
    ++l.res.steps;
    if (l.ray->visit(step, l.res)) return end_ray(i, false);
    const RayState yi = dp.y(i);
    if (st.captured({yi[0], yi[1], yi[2], yi[3]})) {
      l.res.reason = StopReason::horizon;
      l.res.lambda = capture_crossing(st, step);
      l.res.y = step.at(l.res.lambda);
      return end_ray(i, false);
    }
    const double rho2 = yi[1] * yi[1] + yi[2] * yi[2] + yi[3] * yi[3];
    const bool outward = yi[1] * dp.slope(i, 1) + yi[2] * dp.slope(i, 2) + yi[3] * dp.slope(i, 3) > 0.0;
    if (!l.relaxed && rho2 > free2 && outward) {
      dp.relax(i, free_flight_relaxation);
      l.relaxed = true;
    }
    if (rho2 > R2 && outward) {
      l.res.reason = StopReason::escaped;
      end_ray(i, true);
    } else if (l.res.steps >= opt.max_steps) {
      l.res.reason = StopReason::step_limit;
      end_ray(i, true);
    }
  };
  auto gave_up = [&](int i) {
    lanes[i].res.reason = StopReason::gave_up;
    end_ray(i, true);
  };
  while (dp.attempt(accepted, gave_up)) {
  }
}

// Calls f (which must not be inlined here) with the stack moved to the same
// offset within a 4 KiB page, whoever the caller.  The lane integrators keep
// ~10 KB of state on the stack, and where it falls within a page is worth up
// to 18% of a Kerr frame: a change to the renderer's row loop that moved it
// by 16 bytes did that (the same code took 9.0 s or 10.8 s for six
// kerr_accrDisk frames; 4K aliasing is the likely cause, the machine's
// counters could not show it).  Pinned, the integrator's placement no
// longer depends on its callers' frames.
template <class F>
[[gnu::noinline]] void on_pinned_stack(F&& f) {
  constexpr std::uintptr_t page = 4096, offset = 0;
  const auto sp = reinterpret_cast<std::uintptr_t>(__builtin_frame_address(0));
  volatile char* pad = static_cast<char*>(__builtin_alloca((sp - offset) % page + 1));
  pad[0] = 0;
  f();
  pad[0] = 1;  // keeps the pad alive across the call
}

}  // namespace detail

// Traces the camera rays of local directions `dirs` (on the observer's
// legs) into `out` (same size), as trace_sample does one by one.
template <class S>
void trace_batch(const SceneOf<S>& sc, std::span<const Vec3> dirs, std::span<RaySample> out) {
  detail::on_pinned_stack([&]() __attribute__((noinline)) {
    if constexpr (std::is_same_v<S, Kerr>) {
      if (sc.spheres.empty() && sc.rays.kerr_chart == KerrChart::boyer_lindquist_mino)
        return detail::trace_mino_lanes(sc, dirs, out);
    } else if constexpr (std::is_same_v<S, Dihole>) {
      return detail::trace_hamiltonian_lanes(sc, DiholeRhs4(sc.spacetime), dirs, out);
    }
    for (std::size_t k = 0; k < dirs.size(); ++k) out[k] = trace_sample(sc, dirs[k], NoPath{});
  });
}

}  // namespace lc
