#pragma once
// How one camera ray ended, as a plain record: the trace stage fills it
// (render/general_path_ray.hpp, render/kerr_fast_path_ray.hpp: both paths the same
// fields), and everything after reads it — the shade stage
// (render/shade.hpp) that turns it into colour, the data layers
// (render/layers.hpp), the sample memo, `lightcone trace` and the star
// stage.  A record holds what was hit and where and how, never a colour,
// so a frame's records can be shaded again without tracing.

#include <array>
#include <cstdint>
#include <limits>

#include "core/color.hpp"
#include "core/hit_kind.hpp"
#include "core/sky_point.hpp"
#include "geodesic/stop_reason.hpp"
#include "objects/surface_point.hpp"

namespace lc {

struct HitRecord {
  HitKind kind = HitKind::gave_up;
  // Which object (kind == object kinds): its index across the scene's
  // object lists (objects/objects.hpp: for_each_object's numbering).
  std::uint32_t object = no_object;
  // How far (coordinate time, either way) the frame's time may move with
  // this sample unchanged, for frames that differ only in time
  // (render/sample_memo.hpp): infinite when the ray never came near where
  // a moving object ever is, else as long as every object it came near
  // stays clear of it; <= 0: no other frame may reuse it.
  float reuse_window = std::numeric_limits<float>::infinity();
  // The event where the ray ended (object hit, capture, escape), in
  // Boyer–Lindquist r and phi (phi in [0, 2 pi)) for Kerr, spherical r and
  // phi about the origin otherwise; t is its scene time minus the frame's
  // observer's.
  double r = 0.0, phi = 0.0, t = 0.0;
  SurfacePoint surface{};  // on the object hit
  // Frequency ratio nu_observed / nu_emitted of the light (docs/light.md):
  // 1 / (p_mu u^mu) with p the ray's momentum (p.u_observer = 1) and u the
  // emitter's 4-velocity; the sky's emitter is at rest far away; 0 for the
  // horizon and rays that gave up.
  double g = 0.0;
  // Its gravitational part where the light model splits g (light/light.hpp:
  // D(u_ref,obs) / D(u_ref,em)); g itself where it does not.
  double g_gravity = 0.0;
  // Where a sky ray went at infinity: theta from +z, phi in [0, 2 pi)
  // (theta < 0: not the sky).
  double sky_theta = -1.0, sky_phi = 0.0;
  // Which of the spacetime's ends (S::ends, spacetime/ends.hpp) a sky ray
  // escaped to or a horizon ray was captured by.
  std::uint8_t spacetime_end = 0;
  int order = 0;  // equatorial-plane crossings before the end
  long steps = 0;
  StopReason reason = StopReason::gave_up;
  // Trace-coordinate state (x^mu, p_mu) where the ray ended, and its affine
  // parameter; the Kerr fast path fills them only when a path is recorded.
  std::array<double, 8> end{};
  double lambda_end = 0.0;

  static constexpr std::uint32_t no_object = 0xffffffffu;
};

// What the shade stage makes of a record (render/shade.hpp): the sample's
// colour (linear RGB) and, for a sky ray, where it went with the light
// model's ratios there (for point stars; the renderer fills the point in
// its pixel).
struct Shading {
  Color color{0.0f, 0.0f, 0.0f};
  SkyPoint sky;
};

// A record and how the shade stage saw it, for the tools that trace one ray
// at a time (render/trace.hpp's trace_sample and trace_batch).  It holds
// its record rather than being one, so a record is never copied into it by
// slicing and a new field of either stays where it belongs.
struct RaySample {
  HitRecord hit;
  Color color{0.0f, 0.0f, 0.0f};
  SkyPoint sky;
};

}  // namespace lc
