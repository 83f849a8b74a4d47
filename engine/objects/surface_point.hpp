#pragma once
// Where on an object a ray met it, in the object's own coordinates: what
// its colour depends on (ObjectKind::surface_at fills it where the ray
// ends, ObjectKind::color_at reads it when the record is shaded).  The
// disk: Boyer–Lindquist r and phi for Kerr, r and phi about the origin
// otherwise; a sphere: its polar angles in its own frame.

namespace lc {

struct SurfacePoint {
  double u = 0.0, v = 0.0;
};

}  // namespace lc
