#pragma once
// The cheap half of an object's step test, for any body that can say where
// it is: a box its centre never leaves, the box its centre stays in over a
// stretch of coordinate time, a tube radius (how far, in coordinates, any
// point of it is from its centre at that point's own time) and its top
// coordinate speed.  From those alone a step of a ray is found clear of it
// (most steps of most rays), and the ray's reuse window narrowed to the
// time the body needs to reach the step.  The sphere (objects/sphere.hpp)
// is built on it; a new bounded kind (a torus, a mesh's box) writes only
// its own exact test for the steps let through.
//
// Assumes a trace chart whose spatial coordinates are Cartesian-like
// (x, y, z as components 1-3 of the state), as the general path's objects
// do (render/general_path_ray.hpp).

#include <algorithm>
#include <utility>
#include <cmath>
#include <concepts>
#include <limits>

#include "core/tensor.hpp"
#include "geodesic/ray_loop.hpp"
#include "objects/step_query.hpp"

namespace lc {

// What a body gives the tests below.
template <class B>
concept BoundedBody = requires(const B& b, double t, Vec3& lo, Vec3& hi) {
  { b.life_lo } -> std::convertible_to<Vec3>;  // the box its centre never leaves
  { b.life_hi } -> std::convertible_to<Vec3>;
  { b.top_speed } -> std::convertible_to<double>;  // |dx/dt| of its centre at most (0 at rest)
  { b.tube_radius() } -> std::convertible_to<double>;
  b.bounds(t, t, lo, hi);  // the box its centre stays in over [t0, t1]
};

inline bool boxes_overlap(const Vec3& alo, const Vec3& ahi, const Vec3& blo, const Vec3& bhi) {
  for (int k = 0; k < 3; ++k)
    if (ahi[k] < blo[k] || bhi[k] < alo[k]) return false;
  return true;
}

// How far from the origin (coordinates) anything of the body ever is
// (ObjectKind::reach).
template <BoundedBody B>
double body_reach(const B& body) {
  double r = 0.0;
  for (int k = 0; k < 3; ++k)
    r = std::max({r, std::abs(body.life_lo[k]) + body.tube_radius(), std::abs(body.life_hi[k]) + body.tube_radius()});
  return r;
}

// How near the origin (coordinates) anything of the body may come: the
// distance from the origin to the box its centre never leaves, less the
// tube's radius; 0 where that box, grown, holds the origin.
template <BoundedBody B>
double body_nearest(const B& body) {
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double out = std::max({body.life_lo[k], -body.life_hi[k], 0.0});
    d2 += out * out;
  }
  return std::max(0.0, std::sqrt(d2) - body.tube_radius());
}

// How near a step may come to a body, by body_near_step's boxes.
enum class BodyReach {
  never,    // clear of everywhere the centre ever is: the body's motion cannot matter
  not_now,  // clear of where the centre is over the step's time range
  maybe,    // the body's exact test must look
};

struct BodyNear {
  BodyReach reach;
  Vec3 lo, hi;  // unless never: the centre's box over the step's time range
};

// For every step of every ray.  First against the box the centre never
// leaves, grown by the tube's radius and half the chord (a step strays from
// its chord by less than that), then against the centre's box over the
// step's time range (for a worldline, a table lookup); neither evaluates
// the step's dense output inside.
template <BoundedBody B>
[[gnu::always_inline]] inline BodyNear body_near_step(const B& body, const RayStep& step) {
  const RayState& a = step.start();
  const double l1 = step.t0 + step.h;
  Vec3 rlo, rhi, clo, chi;
  double chord1 = 0.0, b[4];  // the chord's L1 length: no square root, and >= its length
  for (int k = 0; k < 4; ++k) b[k] = step.component(k, l1);
  for (int k = 0; k < 3; ++k) chord1 += std::abs(b[k + 1] - a[k + 1]);
  const double far = body.tube_radius() + 0.5 * chord1;
  for (int k = 0; k < 3; ++k) {
    rlo[k] = std::min(a[k + 1], b[k + 1]);
    rhi[k] = std::max(a[k + 1], b[k + 1]);
    clo[k] = body.life_lo[k] - far;
    chi[k] = body.life_hi[k] + far;
  }
  BodyNear out{BodyReach::never, {}, {}};
  if (!boxes_overlap(rlo, rhi, clo, chi)) return out;
  body.bounds(a[0], b[0], out.lo, out.hi);
  for (int k = 0; k < 3; ++k) {
    clo[k] = out.lo[k] - far;
    chi[k] = out.hi[k] + far;
  }
  out.reach = boxes_overlap(rlo, rhi, clo, chi) ? BodyReach::maybe : BodyReach::not_now;
  return out;
}

// The distance from the segment a + s (b - a), s in [0, 1], to the box
// [lo, hi].  Its square is convex and quadratic between the s where the
// segment crosses a face's plane, so it is minimised piece by piece.
inline double segment_box_distance(const Vec3& a, const Vec3& b, const Vec3& lo, const Vec3& hi) {
  double cuts[8] = {0.0, 1.0};
  int n = 2;
  for (int k = 0; k < 3; ++k) {
    const double d = b[k] - a[k];
    if (d == 0.0) continue;
    for (const double face : {lo[k], hi[k]}) {
      const double s = (face - a[k]) / d;
      if (s > 0.0 && s < 1.0) cuts[n++] = s;
    }
  }
  // Insertion sort, which std::sort also does below 16 elements: GCC 12
  // warns (-Warray-bounds) of std::sort's 16-element threshold on an
  // 8-element array wherever this is inlined.
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && cuts[j] < cuts[j - 1]; --j) std::swap(cuts[j], cuts[j - 1]);
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i + 1 < n; ++i) {
    // On [s0, s1] each axis is below, inside or above the box throughout:
    // the squared distance is A s^2 + B s + C there.
    const double s0 = cuts[i], s1 = cuts[i + 1], mid = 0.5 * (s0 + s1);
    double A = 0.0, B = 0.0, C = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double d = b[k] - a[k], p = a[k] + mid * d;
      const double face = p < lo[k] ? lo[k] : p > hi[k] ? hi[k] : p;
      if (face == p) continue;
      const double e = a[k] - face;  // offset from the face at s = 0
      A += d * d;
      B += 2.0 * d * e;
      C += e * e;
    }
    const double s = A > 0.0 ? std::clamp(-B / (2.0 * A), s0, s1) : (B > 0.0 ? s0 : s1);
    best = std::min(best, std::max(0.0, (A * s + B) * s + C));
  }
  return std::sqrt(best);
}

// How far (coordinates) the step's hull box stays outside the tube around
// the box [lo, hi] of centres, at least: <= 0 where it may enter it.
template <BoundedBody B>
double hull_box_clearance(const StepHull& h, const B& body, const Vec3& lo, const Vec3& hi) {
  double gap2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double gap = std::max({lo[k] - h.hi[k], h.lo[k] - hi[k], 0.0});
    gap2 += gap * gap;
  }
  return std::sqrt(gap2) - body.tube_radius() - h.margin;
}

// The same, sharper: the step as its chord, strayed from by at most the
// hull's margin.
template <BoundedBody B>
double step_clearance(const RayStep& step, const StepHull& h, const B& body, const Vec3& lo, const Vec3& hi) {
  const RayState& a = step.start();
  return segment_box_distance({a[1], a[2], a[3]}, {h.end[1], h.end[2], h.end[3]}, lo, hi) - body.tube_radius() -
         h.margin;
}

// Grows a box of centres in place by the tube's radius and the step's
// bulge: the tube an exact test clips the step to.
template <BoundedBody B>
void grow_by_reach(const StepHull& h, const B& body, Vec3& lo, Vec3& hi) {
  const double grow = body.tube_radius() + h.margin;
  for (int k = 0; k < 3; ++k) {
    lo[k] -= grow;
    hi[k] += grow;
  }
}

// A step that comes near where the body's centre ever is (near.reach is not
// never) narrows the ray's reuse window to the time the centre needs to
// reach the step's tube: a frame shifted by dt in time finds the centre
// within top_speed |dt| of where it is in this one.  A step that may enter
// the tube closes it (for a body at rest too, though only for rounding: the
// exact tests work in absolute coordinate time, so shifted in time a
// grazing hit could flip).  The hull's box first (a lower bound, no square
// roots past one): only where it would narrow the window does the chord's
// distance sharpen it.
template <BoundedBody B>
void narrow_reuse_window(const B& body, StepTest& t, const BodyNear& near) {
  if (!t.reusable()) return;
  if (!t.tracks_windows()) {
    t.limit_reuse_window(0.0);
    return;
  }
  auto window = [&](double clear) {
    return clear <= 0.0 ? 0.0 : body.top_speed > 0.0 ? clear / body.top_speed : std::numeric_limits<double>::infinity();
  };
  const double box = hull_box_clearance(t.hull(), body, near.lo, near.hi);
  if (window(box) < t.reuse_window())
    t.limit_reuse_window(window(step_clearance(t.step(), t.hull(), body, near.lo, near.hi)));
}

}  // namespace lc
