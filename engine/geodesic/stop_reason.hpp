#pragma once
// Why the integration of a geodesic ended.  Reported explicitly everywhere
// (CSV output, trace output, data layers) so that a "gave up" is never
// mistaken for a physical result.

#include <string_view>

namespace lc {

enum class StopReason {
  horizon,       // captured: inside the capture radius / past the dihole potential bound
  escaped,       // beyond the escape radius and moving outwards
  reached,       // the requested affine parameter, proper time or coordinate time
  hit,           // a scene object stopped the ray (disk, sphere)
  step_limit,    // the maximum number of steps was used up
  gave_up,       // the step size underflowed or the equations left their domain
  no_ray,        // never traced: the camera has no ray through that image point
};

constexpr std::string_view to_string(StopReason r) {
  switch (r) {
    case StopReason::horizon: return "horizon";
    case StopReason::escaped: return "escaped";
    case StopReason::reached: return "reached";
    case StopReason::hit: return "hit";
    case StopReason::step_limit: return "step_limit";
    case StopReason::gave_up: return "gave_up";
    case StopReason::no_ray: return "no_ray";
  }
  return "unknown";
}

}  // namespace lc
