#pragma once
// What a ray found, as the hit.kind data layer records it (docs/layers.md).
// Object kinds say which of these their hits are.  no_ray: the camera has
// no ray through that image point (outside a dome master's disc): never
// traced, black with alpha 0.

namespace lc {

enum class HitKind : int { sky = 0, disk = 1, horizon = 2, object = 3, gave_up = 4, no_ray = 5 };

}  // namespace lc
