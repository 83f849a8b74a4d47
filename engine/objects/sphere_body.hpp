#pragma once
// The sphere as the ray tests see it: its radius, its centre and frame over
// time (free-falling along a worldline, or held at rest), and the box its
// centre never leaves.

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/tensor.hpp"
#include "eye/tetrad.hpp"
#include "worldline/worldline.hpp"

namespace lc {

// The sphere's centre event and frame at the coordinate time of a ray point.
struct SphereFrame {
  Vec4 centre;
  Tetrad frame;
};

struct SphereBody {
  double radius = 1.0;                         // proper radius
  std::shared_ptr<const Worldline> worldline;  // free-falling; else held at rest:
  Vec4 rest_position{};                        // trace coordinates (t ignored)
  Tetrad rest_frame{};
  // Spatial box the centre stays in at all times.
  Vec3 life_lo{}, life_hi{};
  // The fastest its centre moves, |dx/dt| in coordinates (0 at rest).
  double top_speed = 0.0;

  // How far, in coordinates, any point of the sphere may be from the centre
  // at the point's own coordinate time: the spacetime tube's radius.  Set
  // with the placement (Worldline::coordinate_extent; at rest, the rest
  // space's stretch).  About R / U for the paper's dihole sphere (the
  // dihole's spatial metric is U^2 delta, U >= 1, and a moving sphere's
  // Lorentz contraction offsets the tilt of its rest space);
  // docs/architecture.md, "Local objects".
  double tube = 0.0;
  double tube_radius() const { return tube; }

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
};

}  // namespace lc
