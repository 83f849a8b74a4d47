#pragma once
// Camera rays -> ray starts: the stage between a camera's answer
// (camera/camera_sample.hpp) and the trace.  A ray starts from an eye (an
// event and the orthonormal frame there: eye/eye.hpp) along a
// direction on the eye's legs.  Rays from the observer's own event share
// the frame's eye; a displaced eye (stereo) is made here.

#include <deque>
#include <stdexcept>

#include <fmt/format.h>

#include "camera/camera_sample.hpp"
#include "eye/eye.hpp"
#include "eye/tetrad.hpp"
#include "render/scene.hpp"
#include "spacetime/chart.hpp"

namespace lc {

struct RayStart {
  const Eye* eye = nullptr;
  Vec3 direction{};  // unit, on eye->frame's spatial legs
};

// The eye displaced by `offset` (components on the frame eye's spatial
// legs, in M) from the frame's observer, to first order in |offset|: the
// event x + offset^a e_a, the observer's legs there made orthonormal again
// in the metric at the new event (Gram–Schmidt, time leg first), so the
// eye moves with the observer and looks the same way.  Valid while |offset|
// is small against the distance over which the metric changes (far from a
// horizon: there the first-order step may leave the region where the
// observer exists, which throws std::invalid_argument).
template <class S>
Eye displaced_eye(const SceneIn<S>& sc, const Vec3& offset) {
  const S& st = sc.spacetime;
  Eye e = sc.eye;
  for (int mu = 0; mu < 4; ++mu)
    e.event[mu] += offset[0] * sc.eye.frame.e[1][mu] + offset[1] * sc.eye.frame.e[2][mu] +
                   offset[2] * sc.eye.frame.e[3][mu];
  if (st.captured(e.event))
    throw std::invalid_argument(fmt::format("an eye displaced by ({:g}, {:g}, {:g}) M from the observer is inside "
                                            "the capture region of a horizon: move the observer out or the eyes closer",
                                            offset[0], offset[1], offset[2]));
  e.scene_event = st.scene_from_trace(e.event);
  double r_unused, phi_unused;
  scene_polar(st, e.event, e.time, r_unused, phi_unused);
  e.metric = st.metric(e.event);
  try {
    e.frame = orthonormalize(e.metric, sc.eye.frame.e, "displaced eye");
  } catch (const ObserverError& err) {
    throw std::invalid_argument(fmt::format("an eye displaced by ({:g}, {:g}, {:g}) M from the observer: {}",
                                            offset[0], offset[1], offset[2], err.what()));
  }
  if (sc.light.splits()) e.reference = zamo_velocity(st, e.event);
  return e;
}

// The eyes a batch of rays starts from besides the frame's own: kept at
// stable addresses while the batch is traced.
class EyePool {
 public:
  void clear() { eyes_.clear(); }
  // Where the camera ray `r` starts in the scene sc, which must be the
  // scene at the ray's time (the frame's, or the instant of its shutter the
  // sample took: SceneIn::moment), whose eye is the observer there.
  template <class S>
  RayStart start(const SceneIn<S>& sc, const CameraRay& r) {
    if (r.time != sc.moment)
      throw std::logic_error(fmt::format("a camera ray at {:+g} of the frame started in its scene at {:+g}", r.time,
                                         sc.moment));
    if (r.at_observer()) return {&sc.eye, r.direction};
    // A stereo pinhole's eye is the same for a row of rays: made once.
    if (eyes_.empty() || r.eye != last_offset_) {
      eyes_.emplace_back(displaced_eye(sc, r.eye));
      last_offset_ = r.eye;
    }
    return {&eyes_.back(), r.direction};
  }

 private:
  std::deque<Eye> eyes_;
  Vec3 last_offset_{};
};

}  // namespace lc
