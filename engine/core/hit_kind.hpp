#pragma once
// What a ray found, as the hit.kind data layer records it (docs/layers.md).
// The values here are the ends every scene has; each object kind declares
// its own value (ObjectKind::hit_kind, e.g. the disk's 1 and the sphere's 3)
// and its name reports it (render/hit_kind_names.hpp), and the object registry
// checks that no two share one.  no_ray: the camera has no ray through that
// image point (outside a dome master's disc): never traced, black, alpha 0.

namespace lc {

enum class HitKind : int { sky = 0, horizon = 2, gave_up = 4, no_ray = 5 };

}  // namespace lc
