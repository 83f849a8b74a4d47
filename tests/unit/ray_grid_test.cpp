// The star pass's grid of rays (engine/stars/ray_grid.hpp), on a pinhole
// camera's rays in flat space: inside the image a node is its pixel's ray
// (its direction, the point of the pixel it went through); a node beyond the
// edge is extrapolated from the two inside, so at the pixel centres its
// image point is the next centre out exactly and its direction the camera's
// there to second order in the pixel's angle; a node next to a ray that did
// not reach the sky, or extrapolated from one, is unknown.

#include "stars/ray_grid.hpp"

#include <gtest/gtest.h>

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
