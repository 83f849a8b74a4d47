// The patch of sky between four nodes of the rays' grid (engine/stars/
// sky_patch.hpp), on a cube's face seen from its centre (a patch known
// exactly: area 4 pi / 6, centre the face's normal, corners at 1 / sqrt(3)
// from it): its cap and edges, what it may hold (inside the cap but beyond
// an edge: no), and the patches it refuses (a corner unknown, wider than
// allowed); a dart-shaped patch is not convex and may hold all its cap.

#include "stars/sky_patch.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"

namespace lc {
namespace {

GridNode node(const Vec3& v) {
  GridNode n;
  n.sky = unit3(v);
  n.known = true;
  return n;
}

const GridNode face[4] = {node({-1, -1, 1}), node({1, -1, 1}), node({1, 1, 1}), node({-1, 1, 1})};

TEST(SkyPatch, ACubesFaceIsTheKnownPatch) {
  const auto p = make_patch(face[0], face[1], face[2], face[3], -1.0);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->sky.area(), 4 * pi / 6, 1e-14);
  EXPECT_NEAR(p->centre[2], 1.0, 1e-15);
  EXPECT_NEAR(p->cos_reach, 1 / std::sqrt(3.0), 1e-15);
  EXPECT_TRUE(p->convex);
  EXPECT_TRUE(p->may_hold({0, 0, 1}));
  EXPECT_TRUE(p->may_hold(unit3({0.99, 0.5, 1})));
  // Inside the cap (cos 0.64 > 0.577) but beyond the edge x = z.
  EXPECT_FALSE(p->may_hold(unit3({1.2, 0, 1})));
  // Beyond the cap.
  EXPECT_FALSE(p->may_hold(unit3({1, 1, 0.5})));
  EXPECT_FALSE(p->may_hold({0, 0, -1}));
  // Either orientation.
  const auto r = make_patch(face[3], face[2], face[1], face[0], -1.0);
  ASSERT_TRUE(r);
  EXPECT_TRUE(r->convex);
  EXPECT_FALSE(r->may_hold(unit3({1.2, 0, 1})));
}

TEST(SkyPatch, APatchWithAnUnknownCornerOrTooWideIsNone) {
  GridNode missed = face[2];
  missed.known = false;
  EXPECT_FALSE(make_patch(face[0], face[1], missed, face[3], -1.0));
  // The face reaches acos(1 / sqrt 3) = 0.955 rad from its centre.
  EXPECT_FALSE(make_patch(face[0], face[1], face[2], face[3], std::cos(0.95)));
  EXPECT_TRUE(make_patch(face[0], face[1], face[2], face[3], std::cos(0.96)));
}

TEST(SkyPatch, ADartIsNotConvexAndMayHoldItsWholeCap) {
  // Corner 2 pulled in past the diagonal from 1 to 3.
  const auto p = make_patch(face[0], face[1], node({-0.5, -0.5, 1}), face[3], -1.0);
  ASSERT_TRUE(p);
  EXPECT_FALSE(p->convex);
  // In the notch (the triangle of corners 1, 2, 3), outside the dart but
  // inside its cap: may be held, and the exact test says no.
  const Vec3 notch = unit3({-0.17, -0.17, 1});
  EXPECT_TRUE(p->may_hold(notch));
  EXPECT_FALSE(p->sky.locate(notch));
}

}  // namespace
}  // namespace lc
