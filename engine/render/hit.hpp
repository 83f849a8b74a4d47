#pragma once
// What one traced ray (one sample) found: its colour and the data-layer
// values of docs/layers.md.

#include <array>
#include <limits>

#include "core/color.hpp"
#include "core/hit_kind.hpp"
#include "core/sky_point.hpp"
#include "geodesic/stop_reason.hpp"

namespace lc {


// What a ray found, as its integration fills it in.  (The Kerr lanes hold
// one per ray while they integrate, and its size shows in their speed:
// docs/performance.md, changes 25 and 33.)
struct RayHit {
  Color color{0.0f, 0.0f, 0.0f};  // linear RGB
  HitKind kind = HitKind::gave_up;
  // The event where the ray ended (disk or object hit, capture, escape), in
  // Boyer–Lindquist r and phi (phi in [0, 2 pi)) for Kerr, spherical r and
  // phi about the origin otherwise; t is its scene time minus the observer's.
  double r = 0.0, phi = 0.0, t = 0.0;
  // Frequency ratio nu_observed / nu_emitted of the light (docs/light.md):
  // 1 / (p_mu u^mu) with p the ray's momentum (p.u_observer = 1) and u the
  // emitter's 4-velocity; the sky's emitter is at rest far away; 0 for the
  // horizon and rays that gave up.
  double g = 0.0;
  int order = 0;  // equatorial-plane crossings before the end
  // How far (coordinate time, either way) the frame's time may move with
  // this sample unchanged, for frames that differ only in time
  // (render/sample_memo.hpp): infinite when the ray never came near where
  // a moving object ever is, else as long as every object it came near
  // stays clear of it; <= 0: no other frame may reuse it.  (Here it fills
  // padding: RayHit's size shows in the Kerr lanes' speed,
  // docs/performance.md, change 25.)
  float reuse_window = std::numeric_limits<float>::infinity();
  long steps = 0;
  StopReason reason = StopReason::gave_up;
  // Trace-coordinate state (x^mu, p_mu) where the ray ended, and its affine
  // parameter; the Kerr fast path fills them only when a path is recorded.
  std::array<double, 8> end{};
  double lambda_end = 0.0;
};

// One traced ray: what it found, and where a sky ray went (for point
// stars; filled when the ray ends, outside the lanes' state).
struct RaySample : RayHit {
  SkyPoint sky;
};

}  // namespace lc
