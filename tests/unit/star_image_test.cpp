// A star's image in a patch of sky (engine/stars/star_image.hpp), in flat
// space where a patch is its quad's own view: the image lies where the
// camera sees the star (to 1e-3 pixels: within a quad the gnomonic
// projection about its centre is the camera's up to a projective map near
// the identity); at a corner it has that corner's magnification and light
// ratios exactly; a star on the edge or corner that neighbouring patches
// share is placed in exactly one of them; unshifted light is the star's own.

#include "stars/star_image.hpp"

#include <gtest/gtest.h>

#include "star_test_sky.hpp"

namespace lc {
namespace {

using test::Pinhole;

struct Flat {
  Pinhole cam{16, 10, 20};
  std::vector<SkyPoint> rays = cam.sky();  // at the pixel centres
  RayGrid grid{rays, cam.width, cam.height};
  SkyPatch patch(int i, int j) const { return *patch_of(grid, i, j, -1.0); }
};

TEST(StarImage, AnImageIsWhereTheCameraSeesTheStar) {
  const Flat f;
  const SkyPatch p = f.patch(5, 4);  // nodes at (5.5, 4.5) .. (6.5, 5.5)
  for (const auto& [x, y] : {std::pair{5.6, 4.7}, std::pair{6.3, 5.4}, std::pair{6.0, 5.0}}) {
    const auto uv = place_in_patch(p, f.cam.at(x, y));
    ASSERT_TRUE(uv) << x << "," << y;
    const StarImage image = image_at(p, *uv, {1, 1, 1, 1});
    EXPECT_NEAR(image.x, x, 1e-3) << x << "," << y;
    EXPECT_NEAR(image.y, y, 1e-3) << x << "," << y;
    EXPECT_NEAR(image.magnification, 1.0, 1e-15);
  }
  EXPECT_FALSE(place_in_patch(p, f.cam.at(6.6, 5.0)));
  // Its middle, exactly: the bilinear map of the corners at (1/2, 1/2).
  const StarImage mid = image_at(p, {0.5, 0.5}, {1, 2, 3, 4});
  EXPECT_NEAR(mid.x, (p.corner[0].x + p.corner[1].x + p.corner[2].x + p.corner[3].x) / 4, 1e-12);
  EXPECT_NEAR(mid.magnification, 2.5, 1e-15);
}

TEST(StarImage, ACornerCarriesItsOwnMagnificationAndLight) {
  Flat f;
  f.rays[static_cast<std::size_t>(4 * f.cam.width + 5)].color = 1.5f;
  f.rays[static_cast<std::size_t>(4 * f.cam.width + 5)].beaming = 0.5f;
  const SkyPatch p = f.patch(5, 4);
  const auto uv = place_in_patch(p, p.corner[0].sky);
  ASSERT_TRUE(uv);
  const StarImage image = image_at(p, *uv, {7, 1, 1, 1});
  EXPECT_NEAR(image.magnification, 7.0, 1e-9);
  EXPECT_NEAR(image.color, 1.5, 1e-9);
  EXPECT_NEAR(image.beaming, 0.5, 1e-9);
  EXPECT_NEAR(image.x, p.corner[0].x, 1e-9);
}

TEST(StarImage, AStarOnASharedEdgeOrCornerIsInOnePatch) {
  const Flat f;
  // Node (6, 5) is a corner of quads (5..6, 4..5); an edge midpoint between
  // nodes (6, 4) and (6, 5) is on quads (5, 4) and (6, 4).
  const Vec3 corner = f.grid.at(6, 5).sky;
  const GridNode a = f.grid.at(6, 4), b = f.grid.at(6, 5);
  const Vec3 edge = unit3({a.sky[0] + b.sky[0], a.sky[1] + b.sky[1], a.sky[2] + b.sky[2]});
  for (const Vec3& d : {corner, edge}) {
    int placed = 0;
    for (int j = 3; j <= 6; ++j)
      for (int i = 3; i <= 7; ++i) placed += place_in_patch(f.patch(i, j), d) ? 1 : 0;
    EXPECT_EQ(placed, 1);
  }
}

TEST(StarImage, UnshiftedLightIsTheStarsOwn) {
  const StarField field({{{0, 0, 1}, {0.25f, 0.5f, 2.0f}}}, nullptr, nullptr);
  const Color c = seen_light(field, 0, StarImage{0, 0, 3, 1, 1});
  EXPECT_EQ(c[0], 0.25f);
  EXPECT_EQ(c[1], 0.5f);
  EXPECT_EQ(c[2], 2.0f);
}

}  // namespace
}  // namespace lc
