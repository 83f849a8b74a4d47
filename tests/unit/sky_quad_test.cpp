// The sky a quad of pixel centres sees (engine/stars/sky_quad.hpp): solid
// angles against figures known exactly (an octant is 4 pi / 8, a cube face
// seen from the centre 4 pi / 6, a tiny triangle its flat area), and the
// location of a direction in a quad: the corners and edge midpoints where
// they belong, a pinhole camera's quads tiling the sky between them with
// each direction in exactly one.

#include "stars/sky_quad.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/constants.hpp"

namespace lc {
namespace {

Vec3 unit(Vec3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

TEST(SkyQuad, SolidAnglesOfKnownShapes) {
  // Tolerances: rounding, 1e-14 sr; the tiny triangle's flat area differs
  // from its spherical one by O(side^2) relative: 1e-8 at sides of 1e-4.
  EXPECT_NEAR(spherical_triangle_area({1, 0, 0}, {0, 1, 0}, {0, 0, 1}), 4 * pi / 8, 1e-14);
  const SkyQuad face{{unit({-1, -1, 1}), unit({1, -1, 1}), unit({1, 1, 1}), unit({-1, 1, 1})}};
  EXPECT_NEAR(face.area(), 4 * pi / 6, 1e-14);
  const SkyQuad reversed{{face.c[3], face.c[2], face.c[1], face.c[0]}};
  EXPECT_NEAR(reversed.area(), 4 * pi / 6, 1e-14);
  const double s = 1e-4;
  EXPECT_NEAR(spherical_triangle_area(unit({0, 0, 1}), unit({s, 0, 1}), unit({0, s, 1})), 0.5 * s * s, 1e-8 * s * s);
}

TEST(SkyQuad, CornersAndEdgeMidpointsAreWhereTheyBelong) {
  // Tolerance 1e-12: the inversion's rounding.
  const SkyQuad q{{unit({-0.01, -0.02, 1}), unit({0.013, -0.018, 1}), unit({0.011, 0.017, 1}), unit({-0.012, 0.02, 1})}};
  const double uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (int k = 0; k < 4; ++k) {
    const auto at = q.locate(q.c[k]);
    ASSERT_TRUE(at) << k;
    EXPECT_NEAR((*at)[0], uv[k][0], 1e-12) << k;
    EXPECT_NEAR((*at)[1], uv[k][1], 1e-12) << k;
  }
  // The midpoint of the great-circle edge 0-1 is at u = 1/2 only where the
  // projection is symmetric; v = 0 holds on the whole edge.
  const auto edge = q.locate(unit({q.c[0][0] + q.c[1][0], q.c[0][1] + q.c[1][1], q.c[0][2] + q.c[1][2]}));
  ASSERT_TRUE(edge);
  EXPECT_NEAR((*edge)[1], 0.0, 1e-12);
  EXPECT_NEAR((*edge)[0], 0.5, 1e-3);
  EXPECT_FALSE(q.locate(unit({0.05, 0, 1})));
  EXPECT_FALSE(q.locate(unit({0, 0, -1})));
}

TEST(SkyQuad, APinholeCamerasQuadsHoldEachDirectionOnce) {
  // Pixel centres of an 8 x 6 pinhole image with a 40 degree field: their
  // 7 x 5 quads tile the sky between them, so a direction in that region is
  // in exactly one quad (on a shared edge it may be in two: measure zero),
  // and the quads' areas sum to the region's.
  const int W = 8, H = 6;
  const double t = std::tan(20 * degree);
  auto centre = [&](int i, int j) { return unit({(2 * (i + 0.5) / W - 1) * t, (2 * (j + 0.5) / W - H / double(W)) * t, 1}); };
  std::vector<SkyQuad> quads;
  for (int j = 0; j + 1 < H; ++j)
    for (int i = 0; i + 1 < W; ++i) quads.push_back({{centre(i, j), centre(i + 1, j), centre(i + 1, j + 1), centre(i, j + 1)}});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> x(0.0, 1.0);
  int checked = 0;
  for (int n = 0; n < 2000; ++n) {
    const double fi = 0.5 + x(rng) * (W - 1), fj = 0.5 + x(rng) * (H - 1);
    const Vec3 d = unit({(2 * fi / W - 1) * t, (2 * fj / W - H / double(W)) * t, 1});
    int found = 0;
    for (const SkyQuad& q : quads) found += q.locate(d) ? 1 : 0;
    EXPECT_EQ(found, 1) << fi << "," << fj;
    ++checked;
  }
  EXPECT_EQ(checked, 2000);
  // Within a quad of a flat image the bilinear coordinates are the image's
  // own: the gnomonic projection about the quad's centre is the camera's
  // up to a projective map that is near the identity for a small quad.
  const SkyQuad& q = quads[3 * (W - 1) + 2];  // pixel centres (2..3, 3..4)
  const auto at = q.locate(unit({(2 * 2.75 / W - 1) * t, (2 * 3.9 / W - H / double(W)) * t, 1}));
  ASSERT_TRUE(at);
  EXPECT_NEAR((*at)[0], 0.25, 2e-3);
  EXPECT_NEAR((*at)[1], 0.4, 2e-3);
}

}  // namespace
}  // namespace lc
