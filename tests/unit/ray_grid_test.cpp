// The star pass's grid of rays (engine/stars/ray_grid.hpp), on a pinhole
// camera's rays in flat space: inside the image a node is its pixel's ray
// (its direction, the point of the pixel it went through); a node beyond the
// edge is extrapolated from the two inside, so at the pixel centres its
// image point is the next centre out exactly and its direction the camera's
// there to second order in the pixel's angle; a node next to a ray that did
// not reach the sky, or extrapolated from one, is unknown.

#include "stars/ray_grid.hpp"

#include <gtest/gtest.h>

#include "camera/equirect.hpp"
#include "star_test_sky.hpp"

namespace lc {
namespace {

using test::Pinhole;

// The angle (rad) between unit vectors a and b, from their chord (acos of
// their dot product would be good to 1e-8 only).
double angle(const Vec3& a, const Vec3& b) {
  return 2 * std::asin(0.5 * norm3({a[0] - b[0], a[1] - b[1], a[2] - b[2]}));
}

TEST(RayGrid, InsideTheNodesAreThePixelsRays) {
  const Pinhole cam{12, 8, 10};
  const std::vector<SkyPoint> rays = cam.sky(true);
  const RayGrid grid(rays, cam.width, cam.height);
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const GridNode n = grid.at(i, j);
      const double off = i % 2 == 0 ? 0.25 : 0.75;  // adaptive sampling's first samples
      ASSERT_TRUE(n.known);
      EXPECT_EQ(n.x, i + off);
      EXPECT_EQ(n.y, j + off);
      // The sky point's angles round-trip to a few 1e-15 rad.
      EXPECT_LT(angle(n.sky, cam.at(i + off, j + off)), 1e-13) << i << "," << j;
    }
}

TEST(RayGrid, BeyondTheEdgeNodesAreExtrapolated) {
  const Pinhole cam{12, 8, 10};
  const std::vector<SkyPoint> rays = cam.sky();
  const RayGrid grid(rays, cam.width, cam.height);
  // The linear extrapolation of the directions is off by their second
  // difference, under 1% of a pixel's angle (0.015 rad) here.
  const double pixel = 10 * degree / cam.width;
  for (const auto& [i, j] : {std::pair{-1, 3}, std::pair{cam.width, 3}, std::pair{5, -1}, std::pair{5, cam.height},
                             std::pair{-1, -1}, std::pair{cam.width, cam.height}}) {
    const GridNode n = grid.at(i, j);
    ASSERT_TRUE(n.known) << i << "," << j;
    EXPECT_EQ(n.x, i + 0.5) << i << "," << j;
    EXPECT_EQ(n.y, j + 0.5) << i << "," << j;
    EXPECT_LT(angle(n.sky, cam.at(i + 0.5, j + 0.5)), 0.01 * pixel) << i << "," << j;
  }
}

// An image that wraps (a whole sphere's equirectangular frame) makes up no
// ring: across the left and right edges the nodes are the other edge's
// rays, a width away in x; above the top row and below the bottom one, the
// pole, at the image's edge, where the row's rays converge (to second
// order in the ring's size: the first row's centres are 2.8 degrees from
// it here, the ring's mean direction is the pole's to ~1e-9 rad).
TEST(RayGrid, WhereTheImageWrapsTheRingIsTheRaysAcrossTheEdge) {
  EquirectParams p;
  p.yaw = 20;
  p.pitch = 10;
  const EquirectCamera cam(p, 64, 32);
  const std::vector<SkyPoint> rays =
      test::flat_sky([&](double x, double y) { return cam.direction(x, y); }, 64, 32, true);
  const RayGrid grid(rays, 64, 32, cam.wrap());
  for (const int j : {0, 7, 31}) {
    const GridNode left = grid.at(-1, j), last = grid.at(63, j), right = grid.at(64, j), first = grid.at(0, j);
    ASSERT_TRUE(left.known && right.known);
    EXPECT_EQ(left.sky, last.sky);
    EXPECT_EQ(left.x, last.x - 64);
    EXPECT_EQ(left.y, last.y);
    EXPECT_EQ(right.sky, first.sky);
    EXPECT_EQ(right.x, first.x + 64);
  }
  const Vec3 up = cam.axes().up, down = {-up[0], -up[1], -up[2]};
  for (const int i : {-1, 0, 17, 63, 64}) {
    const GridNode top = grid.at(i, -1), bottom = grid.at(i, 32);
    ASSERT_TRUE(top.known && bottom.known) << i;
    EXPECT_LT(angle(top.sky, up), 1e-9) << i;
    EXPECT_LT(angle(bottom.sky, down), 1e-9) << i;
    EXPECT_EQ(top.y, 0.0);
    EXPECT_EQ(bottom.y, 32.0);
    EXPECT_EQ(top.x, grid.at(i, 0).x);
  }
  // A ray of the top row that missed the sky leaves the pole unknown.
  std::vector<SkyPoint> blocked = rays;
  blocked[40].theta = -1;
  EXPECT_FALSE(RayGrid(blocked, 64, 32, cam.wrap()).at(3, -1).known);
  EXPECT_TRUE(RayGrid(blocked, 64, 32, cam.wrap()).at(3, 32).known);
}

TEST(RayGrid, ARayThatMissedTheSkyLeavesItsNodesUnknown) {
  const Pinhole cam{12, 8, 10};
  std::vector<SkyPoint> rays = cam.sky();
  rays[3 * cam.width + 1].theta = -1;  // pixel (1, 3) met an object
  const RayGrid grid(rays, cam.width, cam.height);
  EXPECT_FALSE(grid.at(1, 3).known);
  EXPECT_FALSE(grid.at(-1, 3).known);  // extrapolated from (0, 3) and (1, 3)
  EXPECT_TRUE(grid.at(0, 3).known);
  EXPECT_TRUE(grid.at(-1, 2).known);
}

}  // namespace
}  // namespace lc
