#pragma once
// The one loop every light ray runs in, W rays at a time (core/lanes.hpp:
// one ray in doubles, or one per vector lane), for every formulation of the
// ray equations (geodesic/null_ray.hpp's Hamiltonian in a chart,
// geodesic/kerr_mino.hpp's Boyer–Lindquist–Mino form).  Each lane has its
// own ray — its visitor, which sees every accepted step and may end the ray
// on an object — and its own step size and controller; a lane whose ray ends
// takes the next.  The stopping rules, in this order after each accepted
// step of a lane, are written here once:
//   1. the formulation says the step reached infinity (Mino: u <= 0): the
//      ray is marked escaped before its visitor sees the step;
//   2. the visitor ends the ray (an object hit: it fills the result);
//   3. a ray marked escaped ends;
//   4. captured (Path::captured at the step's end): the ray ends on the
//      capture surface (Path::capture_crossing locates it in the step);
//   5. beyond the free-flight radius, moving on, its tolerances are
//      relaxed once (Path::flight's free; free_flight_relaxation);
//   6. at one of the spacetime's far ends (Path::flight: past the escape
//      radius moving on, in the spacetime's own chart: spacetime/ends.hpp),
//      it has escaped there;
//   7. out of steps (RayOptions::max_steps).
// A ray whose step size underflows gives up.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "core/constants.hpp"
#include "geodesic/dormand_prince.hpp"
#include "geodesic/stop_reason.hpp"
#include "spacetime/ends.hpp"

namespace lc {

using RayState = std::array<double, 8>;
using RayStep = DenseStep<8>;

struct RayResult {
  StopReason reason = StopReason::gave_up;
  RayState y{};       // final state (at the hit for StopReason::hit, set by the visitor)
  double lambda = 0.0;
  long steps = 0;
  std::uint8_t end = 0;  // the far end (an index in S::ends) an escaped ray reached
};

// Runs `count` rays, W at a time.  make_ray(k, slot) emplaces ray k into the
// std::optional `slot`; end(k, ray, result) receives each ray once it has
// ended.  Path (a formulation) provides:
//   template <int W> Rhs<W>   right-hand side on Lanes<W>, with
//                             load(i, const Ray&) for a ray's constants;
//   weights                   per-component error weights;
//   idle()                    a state with a finite right-hand side;
//   at_infinity(y), captured(y), capture_crossing(step, result) -> bool
//   (whether it set the result's end), flight(y, dy) -> Flight: the
//   predicates of the rules above, given y(j) and dy(j), component j of the
//   state and of its slope at the step's end.
// Ray provides start(), slope(), first_step() and visit(step, result).
// Steps are sized by `control`; a ray ends after max_steps.
template <int W, class Path, class MakeRay, class End>
void run_rays(const Path& path, const StepControl& control, long max_steps, std::size_t count, MakeRay&& make_ray,
              End&& end) {
  using Ray = typename Path::Ray;
  using Rhs = typename Path::template Rhs<W>;
  struct Lane {
    std::optional<Ray> ray;
    std::size_t index = 0;
    RayResult res;
    bool relaxed = false;
  };
  std::array<Lane, W> lanes;
  Rhs rhs(path);
  DormandPrince5<8, const Rhs&, W> dp(rhs, control, Path::weights);
  std::size_t next = 0;
  // Starting and ending a ray are out of line, each one copy of its code:
  // inlined at several call sites (the first fill of the lanes, and each
  // rule that ends a ray), the compiler contracted their arithmetic into
  // fused multiply-adds differently at each, and a ray came out ~1e-8 M
  // different depending on which lane it was loaded into (a frame reusing
  // samples then differed from one traced afresh: SampleMemo's test).
  auto load = [&](int i) __attribute__((noinline)) {
    Lane& l = lanes[i];
    if (next >= count) {
      l.ray.reset();
      dp.stop(i, path.idle(), path.idle_slope());
      return;
    }
    l.index = next++;
    make_ray(l.index, l.ray);
    rhs.load(i, *l.ray);
    dp.start(i, l.ray->start(), l.ray->slope(), l.ray->first_step());
    l.res = RayResult{};
    l.relaxed = false;
  };
  // Ends lane i's ray: its state and parameter from the integrator unless
  // set already (an object hit, the capture surface).
  auto finish = [&](int i, bool set_end) __attribute__((noinline)) {
    Lane& l = lanes[i];
    if (set_end) {
      l.res.y = dp.y(i);
      l.res.lambda = dp.t(i);
    }
    end(l.index, *l.ray, l.res);
    load(i);
  };
  for (int i = 0; i < W; ++i) load(i);
  auto accepted = [&](int i, const RayStep& step) {
    Lane& l = lanes[i];
    ++l.res.steps;
    // The lane's state and slope at the step's end, component by component
    // (the predicates read only what they need).
    const auto y = [&](std::size_t j) { return dp.y(i, j); };
    const auto dy = [&](std::size_t j) { return dp.slope(i, j); };
    if (path.at_infinity(y)) l.res.reason = StopReason::escaped;
    if (l.ray->visit(step, l.res)) return finish(i, false);
    if (l.res.reason == StopReason::escaped) return finish(i, true);
    if (path.captured(y)) {
      l.res.reason = StopReason::horizon;
      return finish(i, !path.capture_crossing(step, l.res));
    }
    const Flight f = path.flight(y, dy);
    if (!l.relaxed && f.free) {
      dp.relax(i, free_flight_relaxation);
      l.relaxed = true;
    }
    if (f.escaped) {
      l.res.reason = StopReason::escaped;
      l.res.end = f.end;
      finish(i, true);
    } else if (l.res.steps >= max_steps) {
      l.res.reason = StopReason::step_limit;
      finish(i, true);
    }
  };
  auto gave_up = [&](int i) {
    lanes[i].res.reason = StopReason::gave_up;
    finish(i, true);
  };
  while (dp.attempt(accepted, gave_up)) {
  }
}

}  // namespace lc
