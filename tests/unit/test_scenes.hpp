#pragma once
// Scene pieces several tests build: a checkered sphere on a free-fall
// worldline.

#include "scene/frame_scene.hpp"
#include "objects/sphere.hpp"

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
  sp.worldline = w;
  return sp;
}

}  // namespace lc::test
