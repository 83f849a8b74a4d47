#pragma once
// Scene objects as the ray tracer sees them: the equatorial disk and the sky
// (coordinate objects) and the checkered sphere (a local object riding a
// tetrad along its worldline).

#include <cmath>
#include <memory>

#include "core/constants.hpp"
#include "image/image.hpp"
#include "observer/tetrad.hpp"
#include "scene/frame_scene.hpp"
#include "scene/worldline.hpp"

namespace lc {

// Checker colour of cell (a, b).
inline Color checker(long a, long b, const Color& c0, const Color& c1) { return ((a + b) & 1) == 0 ? c0 : c1; }

struct Disk {
  DiskSpec spec;
  // Colour at Boyer–Lindquist (r, phi), r in [inner, outer], phi in [0, 2 pi).
  Color color(double r, double phi) const {
    const long ring = static_cast<long>(std::floor((r - spec.inner) / (spec.outer - spec.inner) * spec.rings));
    const long sector = static_cast<long>(std::floor(phi / two_pi * spec.sectors));
    return checker(ring, sector, spec.color_a, spec.color_b);
  }
};


// The sphere's centre event and frame at the coordinate time of a ray point.
struct SphereFrame {
  Vec4 centre;
  Tetrad frame;
};

struct Sphere {
  SphereSpec spec;
  std::shared_ptr<const Worldline> worldline;  // free-falling; else held at rest:
  Vec4 rest_position{};                        // trace coordinates (t ignored)
  Tetrad rest_frame{};

  SphereFrame at(double t) const {
    if (worldline) {
      const WorldlineEvent ev = worldline->at_coordinate_time(t);
      return {ev.x, ev.frame};
    }
    Vec4 c = rest_position;
    c[0] = t;
    return {c, rest_frame};
  }
  // The centre and its 4-velocity at coordinate time t, without the frame.
  void centre(double t, Vec4& x, Vec4& u) const {
    if (worldline) return worldline->centre_at_coordinate_time(t, x, u);
    x = rest_position;
    x[0] = t;
    u = rest_frame.e[0];
  }
  // Spatial box the centre stays in over [t0, t1].
  void bounds(double t0, double t1, Vec3& lo, Vec3& hi) const {
    if (worldline) return worldline->bounds(t0, t1, lo, hi);
    lo = hi = {rest_position[1], rest_position[2], rest_position[3]};
  }
  // Spatial box the centre stays in at all times (set by the scene builder
  // from the worldline, or the rest position).
  Vec3 life_lo{}, life_hi{};
  // Colour at local direction xi (on the frame's legs): checker in the
  // sphere's own polar angles, pole along the third leg.
  Color color(const Vec3& xi) const {
    const double th = std::acos(std::clamp(xi[2] / norm3(xi), -1.0, 1.0));
    double ph = std::atan2(xi[1], xi[0]);
    if (ph < 0) ph += two_pi;
    return checker(static_cast<long>(th / pi * spec.rows), static_cast<long>(ph / two_pi * spec.columns),
                   spec.color_a, spec.color_b);
  }
};

}  // namespace lc
