// The cheap half of an object's step test (objects/bounded_body.hpp), for
// a toy body written here with nothing but what the helper asks for: a
// coordinate ball whose centre moves at constant velocity.  The helper's
// answers are checked against brute force along straight steps.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "objects/bounded_body.hpp"
#include "objects/sphere.hpp"

namespace lc {
namespace {

// A ball of coordinate radius `radius` whose centre moves from c0 at
// velocity v over coordinate times [t_begin, t_end] (held at its ends
// outside them).
struct ToyBall {
  Vec3 c0{}, v{};
  double t_begin = -10.0, t_end = 10.0, radius = 1.0;
  Vec3 life_lo{}, life_hi{};
  double top_speed = 0.0;

  ToyBall(const Vec3& start, const Vec3& velocity, double r) : c0(start), v(velocity), radius(r) {
    bounds(t_begin, t_end, life_lo, life_hi);
    top_speed = norm3(v);
  }
  double tube_radius() const { return radius; }
  Vec3 centre(double t) const {
    const double s = std::clamp(t, t_begin, t_end);
    return {c0[0] + v[0] * s, c0[1] + v[1] * s, c0[2] + v[2] * s};
  }
  void bounds(double t0, double t1, Vec3& lo, Vec3& hi) const {
    const Vec3 a = centre(std::min(t0, t1)), b = centre(std::max(t0, t1));
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(a[k], b[k]);
      hi[k] = std::max(a[k], b[k]);
    }
  }
};
static_assert(BoundedBody<ToyBall>);
static_assert(BoundedBody<Sphere>, "the sphere is built on the helper");

// A straight step from event a to event b (light in flat space when
// |b - a| spatial equals b.t - a.t): the dense output is linear.
RayStep straight_step(const Vec4& a, const Vec4& b) {
  RayStep s;
  s.t0 = 0.0;
  s.h = 1.0;
  for (int k = 0; k < 4; ++k) {
    s.r1[k] = a[k];
    s.r2[k] = b[k] - a[k];
  }
  return s;
}

// The least distance of the step's points from the ball's centre at each
// point's own time, by sampling (steps here are at most 6 long and 6 M: a
// sample every 1e-4 of one misses by at most ~1e-3).
double brute_clearance(const ToyBall& ball, const RayStep& step) {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 10000; ++i) {
    const RayState y = step.at(i / 10000.0);
    const Vec3 c = ball.centre(y[0]);
    best = std::min(best, std::hypot(y[1] - c[0], y[2] - c[1], y[3] - c[2]) - ball.radius);
  }
  return best;
}

TEST(BoundedBody, ReachIsTheFarthestPointOfItsLife) {
  const ToyBall ball({1, 0, 0}, {0.5, 0, 0}, 2.0);  // centre from x = -4 to x = 6
  EXPECT_DOUBLE_EQ(body_reach(ball), 8.0);
}

// A step the helper calls clear (never, or not now) never comes within the
// ball; a step that enters the ball is always "maybe".  Random steps of
// light, near and far, past a ball at rest and a moving one.
TEST(BoundedBody, AStepCalledClearNeverMeetsTheBall) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-8.0, 8.0), len(0.5, 6.0), when(-12.0, 12.0);
  int counts[3] = {0, 0, 0};
  for (const Vec3 v : {Vec3{0, 0, 0}, Vec3{0.6, 0.0, 0.3}}) {
    const ToyBall ball({0, 0, 0}, v, 1.5);
    for (int n = 0; n < 3000; ++n) {
      Vec3 d{u(rng), u(rng), u(rng)};
      const double l = len(rng), nd = norm3(d);
      const Vec4 a{when(rng), u(rng), u(rng), u(rng)};
      const Vec4 b{a[0] - l, a[1] + l * d[0] / nd, a[2] + l * d[1] / nd, a[3] + l * d[2] / nd};  // into the past
      const RayStep step = straight_step(a, b);
      const BodyNear near = body_near_step(ball, step);
      ++counts[static_cast<int>(near.reach)];
      const double clear = brute_clearance(ball, step);
      if (near.reach != BodyReach::maybe) {
        EXPECT_GT(clear, -1e-9) << n;
      }
      if (clear < -1e-2) {
        EXPECT_EQ(near.reach, BodyReach::maybe) << n;
      }
    }
  }
  // The draw reaches all three answers, so each branch was checked.
  EXPECT_GT(counts[0], 100);
  EXPECT_GT(counts[1], 100);
  EXPECT_GT(counts[2], 100);
}

// The reuse window a step leaves: the time the centre needs, at its top
// speed, to come within the ball's radius of the step; infinite for a ball
// at rest that the step passes clear of, 0 for a step that may enter it.
TEST(BoundedBody, TheReuseWindowIsTheTimeTheBodyNeedsToReachTheStep) {
  // A step along y at x = 3.6, from t = 0 back to t = -4; the moving
  // ball's centre is on the x axis within [0, 1] at all times (speed 0.05
  // over 20 M), so the step comes near where it ever is (within its radius
  // and half the chord) but not where it is over the step's times.
  const RayStep step = straight_step({0, 3.6, -2, 0}, {-4, 3.6, 2, 0});
  // The window the step leaves after the helper saw `ball` (from "unlimited").
  auto window_after = [&](const ToyBall& ball, bool tracks_windows) {
    ObjectWarmStarts warm = no_warm_starts();
    float window = 1e30f;
    StepTest t(step, window, tracks_windows, warm);
    narrow_reuse_window(ball, t, body_near_step(ball, step));
    return window;
  };
  const ToyBall moving({0.5, 0, 0}, {0.05, 0, 0}, 1.0);
  ASSERT_EQ(body_near_step(moving, step).reach, BodyReach::not_now);
  // Over the step's times the centre is within x in [0.3, 0.5]: the step
  // is 3.1 away from that box, the ball's radius 1 of it, the straight
  // step strays by nothing (its margin is rounding); the window is a
  // float rounded down (an ulp at 42 is 3.8e-6).
  EXPECT_NEAR(window_after(moving, true), (3.1 - 1.0) / 0.05, 2e-5);
  EXPECT_GT(brute_clearance(moving, step), 0.0);

  const ToyBall at_rest({1.0, 0, 0}, {0, 0, 0}, 1.0);  // near, but clear: a body at rest never comes
  ASSERT_NE(body_near_step(at_rest, step).reach, BodyReach::never);
  EXPECT_EQ(window_after(at_rest, true), 1e30f);

  const ToyBall touching({3.1, 0, 0}, {0, 0, 0}, 1.0);
  EXPECT_EQ(body_near_step(touching, step).reach, BodyReach::maybe);
  EXPECT_EQ(window_after(touching, true), 0.0f);

  // A render that does not track windows closes it at any near step.
  EXPECT_EQ(window_after(moving, false), 0.0f);
}

// The reuse window's distance from a step's chord to a box of centres,
// against a brute-force minimum over the segment, for segments that cross,
// graze and miss the box.
TEST(BoundedBody, SegmentToBoxDistanceIsTheClosestApproach) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-6.0, 6.0);
  const Vec3 lo{-1.0, -0.5, 0.0}, hi{2.0, 0.5, 1.5};
  auto to_box = [&](const Vec3& p) {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double g = std::max({lo[k] - p[k], p[k] - hi[k], 0.0});
      d2 += g * g;
    }
    return std::sqrt(d2);
  };
  for (int n = 0; n < 2000; ++n) {
    Vec3 a{coord(rng), coord(rng), coord(rng)}, b{coord(rng), coord(rng), coord(rng)};
    if (n % 4 == 0) b[1] = a[1];  // parallel to a face
    double brute = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 20000; ++i) {
      const double s = i / 20000.0;
      brute = std::min(brute, to_box({a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2])}));
    }
    // The brute force samples every 1/20000 of a segment at most ~21 long.
    const double d = segment_box_distance(a, b, lo, hi);
    EXPECT_LE(d, brute + 1e-12) << n;
    EXPECT_GE(d, brute - 1.1e-3) << n;
  }
  EXPECT_EQ(segment_box_distance({0.5, 0, 0.5}, {5, 5, 5}, lo, hi), 0.0);  // starts inside
}

}  // namespace
}  // namespace lc
