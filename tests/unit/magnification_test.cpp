// Magnification on the star pass's grid (engine/stars/magnification.hpp),
// against figures known without it: in flat space the sky a quad sees is
// its own solid angle, so mu = 1 at every node; a sky that is the camera's
// view shrunk to half its angles (a demagnifying lens) has mu = 4 (to the
// gnomonic map's (1 + r^2)^-3/2 over a 1-degree field: 1e-4); where a patch
// shrinks to a point mu is clamped at the given bound; a node with no patch
// around it has none (0).

#include "stars/magnification.hpp"

#include <gtest/gtest.h>

#include "star_test_sky.hpp"

namespace lc {
namespace {

using test::Pinhole;

TEST(Magnification, InFlatSpaceEveryNodeHasOne) {
  const Pinhole cam{16, 10, 20};
  const std::vector<SkyPoint> rays = cam.sky(true);
  const RayGrid grid(rays, cam.width, cam.height);
  const CameraDirections camera = [&](double x, double y) { return cam.at(x, y); };
  Magnifications mu(grid, camera, std::cos(0.3), 1e4);
  // Away from the edge, the sky's and the camera's directions are the same
  // to the angles' rounding (1e-16 rad over patches of 0.02 rad).
  for (int j = 1; j + 1 < cam.height; ++j)
    for (int i = 1; i + 1 < cam.width; ++i) EXPECT_NEAR(mu.at_node(i, j), 1.0, 1e-9) << i << "," << j;
  // A quad's two areas, the same: its nodes at (4.25, 4.25), (5.75, 4.75),
  // (5.75, 5.75), (4.25, 5.25) span 1.5 pixels.
  const PatchAreas a = mu.areas(4, 4);
  EXPECT_NEAR(a.sky, a.camera, 1e-9 * a.camera);
  EXPECT_NEAR(a.camera, 1.5 * cam.pixel_solid_angle(4, 4), 0.01 * a.camera);
  // Next to the edge and beyond it the sky is extrapolated, the camera's
  // is not: 1%, 3% at the corner beyond the image.
  EXPECT_NEAR(mu.at_node(0, 0), 1.0, 0.01);
  EXPECT_NEAR(mu.at_node(-1, -1), 1.0, 0.03);
  EXPECT_NEAR(mu.at_node(cam.width, 3), 1.0, 0.01);
}

TEST(Magnification, ASkyShrunkToHalfItsAnglesIsMagnifiedFourTimes) {
  const Pinhole cam{16, 10, 1};
  std::vector<SkyPoint> rays = cam.sky();
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const Vec3 d = cam.at(i + 0.5, j + 0.5);
      Pinhole::set_direction(rays[static_cast<std::size_t>(j * cam.width + i)], unit3({d[0] / 2, d[1] / 2, d[2]}));
    }
  const RayGrid grid(rays, cam.width, cam.height);
  const CameraDirections camera = [&](double x, double y) { return cam.at(x, y); };
  Magnifications mu(grid, camera, std::cos(0.3), 1e4);
  for (int j = 1; j + 1 < cam.height; ++j)
    for (int i = 1; i + 1 < cam.width; ++i) EXPECT_NEAR(mu.at_node(i, j), 4.0, 4e-4) << i << "," << j;
}

TEST(Magnification, APatchShrunkToAPointIsClampedAndNoPatchIsNone) {
  const Pinhole cam{8, 6, 10};
  std::vector<SkyPoint> rays = cam.sky();
  for (SkyPoint& p : rays) Pinhole::set_direction(p, {0, 0, 1});  // every ray to one point: a caustic
  rays[0].theta = -1;                                              // pixel (0, 0) met an object
  const RayGrid grid(rays, cam.width, cam.height);
  const CameraDirections camera = [&](double x, double y) { return cam.at(x, y); };
  Magnifications mu(grid, camera, std::cos(0.3), 250.0);
  EXPECT_NEAR(mu.at_node(4, 3), 250.0, 1e-9);
  EXPECT_EQ(mu.areas(-1, -1).camera, 0.0);  // its corners are all (0, 0) or extrapolated from it
  EXPECT_EQ(mu.at_node(-1, -1), 0.0);
}

}  // namespace
}  // namespace lc
