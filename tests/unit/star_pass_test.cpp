// Stars as points on a finished frame (engine/stars/star_pass.hpp), in flat
// space where the sky a pixel sees is its own solid angle: a star's light
// lands within the 2 x 2 pixels around it at any field of view, its total
// (radiance times each pixel's solid angle) is conserved to 1% and its
// centroid follows it as it pans across pixels in tenth-pixel steps
// (landing exactly on the rays' lines too: counted once), whether the rays
// pass through the pixel centres or (adaptive sampling's first samples) a
// quarter pixel off them, alternating along the row; glare spreads a share
// of the light wider and keeps it; a star behind an object (a pixel whose
// ray did not reach the sky) is not drawn.

#include "stars/star_pass.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "camera/equirect.hpp"
#include "core/constants.hpp"
#include "star_test_sky.hpp"
#include "stars/sky_quad.hpp"

namespace lc {
namespace {

using test::Pinhole;

struct Seen {
  double total = 0.0, x = 0.0, y = 0.0;  // sum of radiance x pixel solid angle (first channel), its centroid
  int lit = 0, min_i = 1 << 30, max_i = -1, min_j = 1 << 30, max_j = -1;
};

Seen render(const Pinhole& cam, const std::vector<SkyPoint>& sky, const Vec3& star, double glare = 0.0) {
  const StarField field({{star, {1.0f, 1.0f, 1.0f}}}, nullptr, nullptr);
  std::vector<float> image(3 * static_cast<std::size_t>(cam.width * cam.height), 0.0f);
  StarPassOptions o;
  o.glare = glare;
  o.glare_radius = 1.5;
  add_point_stars(sky, cam.width, cam.height, field, [&](double x, double y) { return cam.at(x, y); }, o, image);
  Seen s;
  for (int j = 0; j < cam.height; ++j)
    for (int i = 0; i < cam.width; ++i) {
      const float r = image[3 * static_cast<std::size_t>(j * cam.width + i)];
      if (r <= 0) continue;
      const double f = r * cam.pixel_solid_angle(i, j);
      s.total += f;
      s.x += f * (i + 0.5);
      s.y += f * (j + 0.5);
      ++s.lit;
      s.min_i = std::min(s.min_i, i), s.max_i = std::max(s.max_i, i);
      s.min_j = std::min(s.min_j, j), s.max_j = std::max(s.max_j, j);
    }
  s.x /= s.total;
  s.y /= s.total;
  return s;
}

TEST(StarPass, AStarIsSharpAndItsLightConservedAsItPans) {
  for (const bool adaptive : {false, true})
    for (const double fov : {1.0, 20.0, 60.0, 120.0}) {
      const Pinhole cam{64, 36, fov};
      const std::vector<SkyPoint> sky = cam.sky(adaptive);
      double lo = 1e300, hi = 0;
      for (int step = 0; step <= 20; ++step) {
        const double x = 30.3 + 0.1 * step, y = 17.45 + 0.037 * step;
        const Seen s = render(cam, sky, cam.at(x, y));
        const std::string where = "fov " + std::to_string(fov) + (adaptive ? " adaptive" : "") + " x " + std::to_string(x);
        EXPECT_LE(s.max_i - s.min_i, 1) << where;  // within the 2 x 2 pixel filter
        EXPECT_LE(s.max_j - s.min_j, 1) << where;
        // The centroid within 0.05 pixels (wide fields stretch the pixels
        // unevenly across the filter).
        EXPECT_NEAR(s.x, x, 0.05) << where;
        EXPECT_NEAR(s.y, y, 0.05) << where;
        lo = std::min(lo, s.total), hi = std::max(hi, s.total);
      }
      EXPECT_NEAR(lo, 1.0, 0.01) << "fov " << fov << (adaptive ? " adaptive" : "");
      EXPECT_NEAR(hi, 1.0, 0.01) << "fov " << fov << (adaptive ? " adaptive" : "");
    }
}

TEST(StarPass, GlareSpreadsAShareOfTheLightAndKeepsIt) {
  const Pinhole cam{64, 36, 20};
  const Seen sharp = render(cam, cam.sky(), cam.at(30.3, 17.6));
  const Seen glared = render(cam, cam.sky(), cam.at(30.3, 17.6), 0.3);
  EXPECT_NEAR(glared.total, sharp.total, 0.01 * sharp.total);
  // Out to where the halo is under a thousandth of the faintest star's
  // light on a pixel (here the star itself): ~3 pixels each way.
  EXPECT_GE(glared.max_i - glared.min_i, 5);
}

TEST(StarPass, StarsAtTheImagesEdgeAndBehindObjects) {
  const Pinhole cam{32, 18, 40};
  std::vector<SkyPoint> sky = cam.sky();
  // At the outermost pixel centres, all of a star's light is in the image;
  // between them and the edge it is still drawn (from directions
  // extrapolated beyond it), the pixel filter's share outside it lost: 0.7
  // of it at 0.3 pixels from the edge.  Tolerance 2%: the extrapolated
  // directions make the outer patches ~1% off the true pixels' solid angle.
  EXPECT_NEAR(render(cam, sky, cam.at(0.5, 9.0)).total, 1.0, 0.02);
  EXPECT_NEAR(render(cam, sky, cam.at(0.2, 9.0)).total, 0.7, 0.02);
  // Outside the image: nothing.
  EXPECT_EQ(render(cam, sky, cam.at(-3.0, 9.0)).lit, 0);
  // Pixel (10, 5) met an object: a star beside its centre is hidden.
  sky[5 * 32 + 10].theta = -1;
  EXPECT_EQ(render(cam, sky, cam.at(10.6, 5.6)).lit, 0);
}

// A whole sphere's equirectangular frame has no edges: a star panned
// across the seam (x = 0 = W) or over a pole in tenth-pixel steps keeps its
// light (within 2%: the pole's patches come from the mean of the first
// row's rays, and pixels there are narrow wedges) and lands only on the
// pixels around where it is, never twice and never lost, with and without
// adaptive sampling's offset rays.
TEST(StarPass, OnAWholeSphereAStarCrossesTheSeamAndThePolesWhole) {
  const int W = 64, H = 32;
  EquirectParams p;
  p.yaw = 30;
  p.pitch = -20;
  const EquirectCamera cam(p, W, H);
  auto at = [&](double x, double y) { return cam.direction(x, y); };
  StarPassOptions o;
  o.wrap = cam.wrap();
  ASSERT_TRUE(o.wrap.columns && o.wrap.poles);
  auto draw = [&](const std::vector<SkyPoint>& sky, const Vec3& star) {
    const StarField field({{star, {1.0f, 1.0f, 1.0f}}}, nullptr, nullptr);
    std::vector<float> image(3 * static_cast<std::size_t>(W * H), 0.0f);
    const long images = add_point_stars(sky, W, H, field, at, o, image);
    Seen s;
    for (int j = 0; j < H; ++j)
      for (int i = 0; i < W; ++i) {
        const float r = image[3 * static_cast<std::size_t>(j * W + i)];
        if (r <= 0) continue;
        s.total += r * SkyQuad{{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}}.area();
        ++s.lit;
        s.min_i = std::min(s.min_i, i), s.max_i = std::max(s.max_i, i);
        s.min_j = std::min(s.min_j, j), s.max_j = std::max(s.max_j, j);
      }
    EXPECT_EQ(images, 1);
    return s;
  };
  for (const bool adaptive : {false, true}) {
    const std::vector<SkyPoint> sky = test::flat_sky(at, W, H, adaptive);
    const std::string how = adaptive ? " adaptive" : "";
    for (int step = 0; step <= 20; ++step) {
      // Across the seam, on row 9.
      const double x = W - 1.0 + 0.1 * step;
      const Seen s = draw(sky, cam.direction(x, 9.3));
      EXPECT_NEAR(s.total, 1.0, 0.02) << "x " << x << how;
      EXPECT_LE(s.max_j - s.min_j, 1) << "x " << x << how;
      for (int i : {s.min_i, s.max_i})  // only the columns either side of the seam
        EXPECT_TRUE(i >= W - 2 || i <= 1) << "x " << x << " lit column " << i << how;
      // Over the north pole: from a pixel below it on column 10.3 up and
      // down the other side (column 42.3), passing it at 0.05 pixels.
      const double y = -1.05 + 0.1 * step;
      const Seen n = draw(sky, cam.direction(10.3, y));
      EXPECT_NEAR(n.total, 1.0, 0.02) << "y " << y << how;
      EXPECT_LE(n.max_j, 1) << "y " << y << how;
    }
    // And a hair from the south pole.
    EXPECT_NEAR(draw(sky, cam.direction(5.0, H - 0.01)).total, 1.0, 0.02) << how;
  }
}

// The pass on several threads: rows of tiles and bands of pixels are
// worked out apart and joined in a fixed order, so the image is the same
// to the bit for any thread count.  A lens-like sky (a point lens's map:
// a shadow, two images of each star, a crowded ring) of 3,000 stars with
// glare, on an odd-sized image (rows of tiles cut short at its edge).
TEST(StarPass, TheImageIsTheSameToTheBitOnAnyNumberOfThreads) {
  const Pinhole cam{97, 61, 60};
  const std::vector<SkyPoint> sky = test::point_lens_sky(cam, 0.15);  // Einstein angle 0.15 rad
  std::vector<PointStar> stars;
  unsigned long seed = 12345;
  auto uniform = [&seed] {
    seed = seed * 6364136223846793005UL + 1442695040888963407UL;
    return static_cast<double>(seed >> 11) / 9007199254740992.0;
  };
  for (int k = 0; k < 3000; ++k)
    stars.push_back({unit3({uniform() - 0.5, (uniform() - 0.5) * 0.7, 1}),
                     Color{static_cast<float>(0.1 + uniform()), 1.0f, static_cast<float>(0.5 + uniform())}});
  const StarField field(stars, nullptr, nullptr);
  StarPassOptions o;
  o.glare = 0.1;
  o.glare_radius = 1.5;
  auto draw = [&](int threads, long& images, double& cpu) {
    std::vector<float> image(3 * static_cast<std::size_t>(cam.width * cam.height), 0.25f);
    o.threads = threads;
    cpu = 0.0;
    images = add_point_stars(sky, cam.width, cam.height, field, [&](double x, double y) { return cam.at(x, y); }, o,
                             image, &cpu);
    return image;
  };
  long one_images = 0;
  double one_cpu = 0.0;
  const std::vector<float> one = draw(1, one_images, one_cpu);
  EXPECT_GT(one_images, 1000) << "too few images to test anything";
  EXPECT_GT(one_cpu, 0.0);
  for (const int threads : {2, 3, 7, 64}) {
    long images = 0;
    double cpu = 0.0;
    const std::vector<float> many = draw(threads, images, cpu);
    EXPECT_EQ(images, one_images) << threads << " threads";
    EXPECT_GT(cpu, 0.0) << threads << " threads";
    EXPECT_EQ(std::memcmp(many.data(), one.data(), one.size() * sizeof(float)), 0) << threads << " threads";
  }
}

}  // namespace
}  // namespace lc
