#pragma once
// The trace and shade stages' calls for a scene in a registered spacetime:
// ray starts (render/ray_start.hpp) -> hit records (render/hit_record.hpp)
// -> colours.  Declared here; their code (render/trace_templates.hpp) is
// compiled once per spacetime, in render/trace_in_<spacetime>.cpp, so what
// renders rows, benches or tests tracing does not include the object kinds
// or the ray formulations (docs/architecture.md, "What a new kind
// rebuilds").  A call per batch or sample costs nothing beside the
// geodesics it follows.

#include <span>

#include "core/tensor.hpp"
#include "render/hit_record.hpp"
#include "render/ray_start.hpp"
#include "render/scene.hpp"

namespace lc {

// What the stages do in spacetime S, compiled where its code is included
// (`template struct TraceStage<S>;` in render/trace_in_<spacetime>.cpp).
template <class S>
struct TraceStage {
  static void records(const SceneIn<S>& sc, std::span<const RayStart> starts, std::span<HitRecord> out);
  static Shading shading(const SceneIn<S>& sc, const HitRecord& hit);
  static RaySample sample(const SceneIn<S>& sc, const RayStart& start);
  static void batch(const SceneIn<S>& sc, std::span<const Vec3> dirs, std::span<RaySample> out);
};

// Traces the rays `starts` into the records `out` (same size), lane_count at
// a time: each record as one ray alone gives it
// (Renderer.LanesGiveWhatOneRayGives).  Colours are the shade stage's.
template <class S>
void trace_records(const SceneIn<S>& sc, std::span<const RayStart> starts, std::span<HitRecord> out) {
  TraceStage<S>::records(sc, starts, out);
}

// The colour of the record `hit` and, for a sky ray, where it went
// (render/shade.hpp).
template <class S>
Shading shading(const SceneIn<S>& sc, const HitRecord& hit) {
  return TraceStage<S>::shading(sc, hit);
}

// Traces the ray `start` (an eye, the frame's or a stereo camera's, and a
// local direction) and shades it.  (With a path recorder:
// render/trace_templates.hpp.)
template <class S>
RaySample trace_sample(const SceneIn<S>& sc, const RayStart& start) {
  return TraceStage<S>::sample(sc, start);
}

// The same along local direction n from the frame's eye.
template <class S>
RaySample trace_sample(const SceneIn<S>& sc, const Vec3& n) {
  return TraceStage<S>::sample(sc, RayStart{&sc.eye, n});
}

// Traces the camera rays of local directions `dirs` from the frame's eye
// into `out` (same size) and shades them: each sample as trace_sample gives
// it.
template <class S>
void trace_batch(const SceneIn<S>& sc, std::span<const Vec3> dirs, std::span<RaySample> out) {
  TraceStage<S>::batch(sc, dirs, out);
}

}  // namespace lc
