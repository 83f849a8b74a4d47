#pragma once
// What the objects' tests share within one accepted step of one ray in the
// general path (render/general_path_ray.hpp): the step, the earliest hit
// found in it so far, the step's hull (made on first use), the ray's
// per-object warm starts, and where it crosses the equatorial plane.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "core/tensor.hpp"
#include "geodesic/crossing.hpp"
#include "geodesic/ray_loop.hpp"

namespace lc {

// Where a step goes, for the sphere tests that their coarse boxes let
// through: the box of its ends and of its points at 1/4, 1/2 and 3/4, and
// how far it may stray beyond: twice the largest distance of those points
// from the chord (a step is a smooth, nearly polynomial arc).  Long straight
// steps (far from the holes) then keep a tight box instead of one grown by a
// fraction of their length.
struct StepHull {
  RayState end{};
  Vec3 lo{}, hi{};
  double chord2 = 0.0;   // squared chord
  double quarter = 0.0;  // the longest chord of a quarter of the step
  double margin = 0.0;   // how far beyond the box the step may stray
};

inline StepHull step_hull(const RayStep& step) {
  StepHull h;
  const double l0 = step.t0, l1 = step.t0 + step.h;
  const RayState& a = step.start();
  const RayState& b = h.end = step.at(l1);
  for (int k = 0; k < 3; ++k) {
    h.chord2 += (b[k + 1] - a[k + 1]) * (b[k + 1] - a[k + 1]);
    h.lo[k] = std::min(a[k + 1], b[k + 1]);
    h.hi[k] = std::max(a[k + 1], b[k + 1]);
  }
  double bulge = 0.0;
  RayState prev = a;
  for (const double q : {0.25, 0.5, 0.75, 1.0}) {
    const RayState m = q == 1.0 ? b : step.at(l0 + q * (l1 - l0));
    double d2 = 0.0, seg2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      h.lo[k] = std::min(h.lo[k], m[k + 1]);
      h.hi[k] = std::max(h.hi[k], m[k + 1]);
      const double off = m[k + 1] - (a[k + 1] + q * (b[k + 1] - a[k + 1]));
      d2 += off * off;
      seg2 += (m[k + 1] - prev[k + 1]) * (m[k + 1] - prev[k + 1]);
    }
    bulge = std::max(bulge, std::sqrt(d2));
    h.quarter = std::max(h.quarter, std::sqrt(seg2));
    prev = m;
  }
  h.margin = 2.0 * bulge + 1e-9 * std::sqrt(h.chord2);
  return h;
}

// Per ray, for the first few objects: a number an object's test carries
// from step to step (a sphere: its last simultaneity answer; NaN: none).
using ObjectWarmStarts = std::array<double, 4>;
inline ObjectWarmStarts no_warm_starts() {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  return {nan, nan, nan, nan};
}

class StepTest {
 public:
  // `reuse_window`: the ray's RayHit::reuse_window, narrowed by the objects
  // the step comes near, worked out only if `track_windows` (else closed by
  // any that comes near a moving object's path).
  StepTest(const RayStep& step, float& reuse_window, bool track_windows, ObjectWarmStarts& warm)
      : step_(step), best_(step.t0 + step.h + 1.0), reuse_window_(reuse_window), track_windows_(track_windows),
        warm_(warm) {
    z0_ = step.start()[3];
    z1_ = step.component(3, step.t0 + step.h);
  }

  const RayStep& step() const { return step_; }
  // The parameter of the earliest hit found in this step so far (beyond the
  // step's end: none), and whether one was.
  double best() const { return best_; }
  bool found() const { return best_ <= step_.t0 + step_.h; }
  void take(double lambda) { best_ = lambda; }

  const StepHull& hull() {
    if (!hull_) hull_ = step_hull(step_);
    return *hull_;
  }
  // Whether another frame may still reuse the ray; narrowing the window to
  // `w` (coordinate time) or less, rounded down.
  bool reusable() const { return reuse_window_ > 0.0f; }
  bool tracks_windows() const { return track_windows_; }
  double reuse_window() const { return reuse_window_; }
  void limit_reuse_window(double w) {
    if (!(w < reuse_window_)) return;
    float f = static_cast<float>(std::max(w, 0.0));
    if (f > w) f = std::nextafter(f, 0.0f);
    reuse_window_ = f;
  }
  // The warm start of the object at `index` among the scene's objects.
  double& warm_start(std::size_t index) {
    scratch_ = std::numeric_limits<double>::quiet_NaN();
    return index < warm_.size() ? warm_[index] : scratch_;
  }

  // Whether the step crosses the equatorial plane z = 0, and where (located
  // from the dense output on first use).
  bool crosses_equator() const { return (z0_ > 0.0) != (z1_ > 0.0) && z0_ != 0.0; }
  double equator_crossing() {
    if (!crossing_) crossing_ = locate_crossing(step_, [](const RayState& y) { return y[3]; }, z0_, z1_);
    return *crossing_;
  }
  bool equator_located() const { return crossing_.has_value(); }

 private:
  const RayStep& step_;
  double best_;
  float& reuse_window_;
  bool track_windows_;
  ObjectWarmStarts& warm_;
  double scratch_ = 0.0;
  std::optional<StepHull> hull_;
  double z0_, z1_;
  std::optional<double> crossing_;
};

}  // namespace lc
