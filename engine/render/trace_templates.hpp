#pragma once
// The trace stage's code (its calls: render/trace.hpp): ray starts
// (render/ray_start.hpp) -> hit records (render/hit_record.hpp), and the
// shade stage after it (render/shade.hpp).  Records are traced lane_count
// at a time (core/lanes.hpp) for the renderer; a sample may also be traced
// alone with a path recorder (`lightcone trace`).  All run the one ray
// loop (geodesic/ray_loop.hpp), and which formulation of the ray equations
// a scene's rays take is chosen here, in one place.  Included where
// TraceStage<S> is compiled, once per registered spacetime
// (render/trace_in_<spacetime>.cpp), and by what traces in a spacetime of
// its own or records paths; the rest includes render/trace.hpp.

#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "core/lanes.hpp"
#include "geodesic/ray_loop.hpp"
#include "render/general_path_ray.hpp"
#include "render/kerr_fast_path_ray.hpp"
#include "render/ray_start.hpp"
#include "render/scene.hpp"
#include "render/shade.hpp"
#include "render/trace.hpp"

namespace lc {

// Whether a scene's rays take the Boyer–Lindquist–Mino fast path: Kerr
// scenes whose objects it handles (objects/objects.hpp: in_fast_path; not a
// sphere, whose worldline and frame live in the trace chart), unless the
// options ask for Kerr–Schild.  Everything else takes the Hamiltonian in the
// trace chart.
template <class S>
bool takes_mino_path(const SceneIn<S>& sc) {
  if constexpr (std::is_same_v<S, Kerr>)
    return objects_in_fast_path(sc.objects->lists) && sc.rays.kerr_chart == KerrChart::boyer_lindquist_mino;
  else
    return false;
}

namespace detail {

// The records of the rays `starts` into `out`, W at a time; on_step records
// paths (NoPath: none).  An out[k] whose reuse_window is 0 on entry asks its
// ray not to work out its window (HamiltonianRay::track_reuse_windows).
template <int W, class S, class OnStep>
void trace_rays(const SceneIn<S>& sc, std::span<const RayStart> starts, std::span<HitRecord> out, OnStep& on_step) {
  // path: the formulation; args: what each ray is made from besides the
  // scene, its direction and the path recorder.
  auto run = [&](const auto& path, const auto&... args) {
    using Ray = typename std::decay_t<decltype(path)>::Ray;
    run_rays<W>(
        path, sc.rays.control, sc.rays.max_steps, starts.size(),
        [&](std::size_t k, std::optional<Ray>& slot) {
          slot.emplace(sc, args..., starts[k], on_step);
          if constexpr (requires(Ray& r) { r.track_reuse_windows(true); })
            slot->track_reuse_windows(out[k].reuse_window > 0.0f);
        },
        [&](std::size_t k, Ray& ray, const RayResult& res) { ray.finish(res, out[k]); });
  };
  if constexpr (std::is_same_v<S, Kerr>) {
    if (takes_mino_path(sc)) {
      const double cr = mino_capture_radius(sc);
      return run(MinoPath<MinoRay<OnStep>>{cr > 0.0 ? 1.0 / cr : 1e300},
                 sc.spacetime.trace_jacobian(sc.eye.scene_event));
    }
  }
  run(HamiltonianPath<S, HamiltonianRay<S, OnStep>>(sc.spacetime, sc.rays));
}

// Calls f (which must not be inlined here) with the stack moved to the same
// offset within a 4 KiB page, whoever the caller.  Why: the lane integrators
// keep ~10 KB of state on the stack, and where it falls within a page decides
// a Kerr frame's speed by up to a fifth, so an unrelated change to a caller's
// locals could slow every frame.  How it was measured: one binary that took
// the offset from the environment rendered the same Kerr frames with offsets
// 0..4032; docs/performance.md, changes 28 and 29, has the numbers.
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

template <class S>
void TraceStage<S>::records(const SceneIn<S>& sc, std::span<const RayStart> starts, std::span<HitRecord> out) {
  detail::on_pinned_stack([&]() __attribute__((noinline)) {
    NoPath no_path;
    detail::trace_rays<lane_count>(sc, starts, out, no_path);
  });
}

// Traces the ray `start` (an eye, the frame's or a stereo camera's, and a
// local direction) and shades it, as render/trace.hpp's trace_sample.  OnStep(const RayState& y, double sigma)
// sees the start of every accepted step in trace coordinates with its
// affine parameter (for `lightcone trace`; NoPath when rendering).
template <class S, class OnStep>
RaySample trace_sample(const SceneIn<S>& sc, const RayStart& start, OnStep&& on_step) {
  RaySample out;
  detail::trace_rays<1>(sc, std::span<const RayStart>(&start, 1), std::span<HitRecord>(&out.hit, 1), on_step);
  shade(sc, out);
  return out;
}

// The same along local direction n from the frame's eye.
template <class S, class OnStep>
RaySample trace_sample(const SceneIn<S>& sc, const Vec3& n, OnStep&& on_step) {
  return trace_sample(sc, RayStart{&sc.eye, n}, on_step);
}

template <class S>
void TraceStage<S>::batch(const SceneIn<S>& sc, std::span<const Vec3> dirs, std::span<RaySample> out) {
  std::vector<RayStart> starts(dirs.size());
  std::vector<HitRecord> records(dirs.size());
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    starts[k] = {&sc.eye, dirs[k]};
    records[k].reuse_window = out[k].hit.reuse_window;
  }
  TraceStage<S>::records(sc, std::span<const RayStart>(starts), std::span<HitRecord>(records));
  for (std::size_t k = 0; k < dirs.size(); ++k) {
    out[k].hit = records[k];
    shade(sc, out[k]);
  }
}

template <class S>
Shading TraceStage<S>::shading(const SceneIn<S>& sc, const HitRecord& hit) {
  return shade(sc, hit);
}

template <class S>
RaySample TraceStage<S>::sample(const SceneIn<S>& sc, const RayStart& start) {
  return trace_sample(sc, start, NoPath{});
}

}  // namespace lc
