#pragma once
// Scene pieces several tests build: a checkered sphere on a free-fall
// worldline; the dihole oscillation that worldlines are checked against,
// and where a sampled swing turns back.

#include "geodesic/geodesic_solver.hpp"
#include "objects/sphere.hpp"
#include "scene/scene_spec.hpp"
#include "spacetime/dihole.hpp"

namespace lc::test {

// A sphere of `radius` free-falling in `spacetime` from `start` with
// 3-velocity `velocity` (relative to the static observer there), for
// `duration` of proper time.
inline Sphere::Params falling_sphere(const Spacetime& spacetime, const Vec4& start, const Vec3& velocity, double duration,
                                 double radius) {
  WorldlineSpec w;
  w.spacetime = spacetime;
  w.start = start;
  w.velocity = velocity;
  w.duration = duration;
  w.where = "test";
  Sphere::Params sp;
  sp.radius = radius;
  sp.placement.at = w;
  return sp;
}

// The paper's dihole test body as a reference-solver problem: released at
// rest (the static observer's 4-velocity) at (5, 0, 0) between masses 0.4
// at z = +-1, it falls through the origin to x = -5 and back; solved until
// `stop` reaches `stop_value`.
inline GeodesicProblem dihole_oscillation_problem(StopParameter stop, double stop_value) {
  const Dihole d(0.4, 0.4, 1.0);
  GeodesicProblem pb;
  pb.spacetime = d;
  pb.kind = CurveKind::timelike;
  pb.x0 = {0, 5, 0, 0};
  pb.u0 = static_cartesian_tetrad(d, pb.x0).e[0];
  pb.stop_parameter = stop;
  pb.stop_value = stop_value;
  return pb;
}

// Where a sampled swing turns back: the coordinate and proper time at
// which u^axis first turns from positive to non-positive after coordinate
// time `after`, linear between the samples (-1 where it never does).
struct Turn {
  double t = -1.0, tau = -1.0;
};
inline Turn turn_after(const GeodesicPath& path, int axis, double after) {
  for (std::size_t i = 1; i < path.samples.size(); ++i) {
    const auto& a = path.samples[i - 1];
    const auto& b = path.samples[i];
    if (a.x[0] > after && a.u[axis] > 0 && b.u[axis] <= 0) {
      const double f = a.u[axis] / (a.u[axis] - b.u[axis]);
      return {a.x[0] + f * (b.x[0] - a.x[0]), a.lambda + f * (b.lambda - a.lambda)};
    }
  }
  return {};
}

}  // namespace lc::test
