// The star pass's last stages (engine/stars/pixel_deposits.hpp,
// glare_kernel.hpp, pixel_light.hpp) against what a tent filter, a
// normalised halo and a pixel's solid angle are: an image's light lands on
// the 2 x 2 pixels around it, summing to its own with its centroid at its
// place (exactly, as a bilinear filter's does), all on one pixel at that
// pixel's centre, part lost beyond the image's edge (0.7 of it 0.2 pixels
// in from the edge: the tent's share there); deposits on one pixel sum;
// radiance times the pixel's solid angle is the flux; the halo's weights
// sum to 1 and the light spread with glare is kept.

#include "stars/pixel_deposits.hpp"

#include <gtest/gtest.h>

#include "star_test_sky.hpp"
#include "stars/glare_kernel.hpp"
#include "stars/pixel_light.hpp"

namespace lc {
namespace {

struct Sum {
  double light = 0.0, x = 0.0, y = 0.0;
};

Sum summed(const std::vector<Deposit>& ds) {
  Sum s;
  for (const Deposit& d : ds) {
    s.light += d.flux[0];
    s.x += d.flux[0] * (d.i + 0.5);
    s.y += d.flux[0] * (d.j + 0.5);
  }
  s.x /= s.light;
  s.y /= s.light;
  return s;
}

TEST(PixelDeposits, TheTentFilterKeepsTheLightAndItsCentroid) {
  for (const auto& [x, y] : {std::pair{10.5, 5.5}, std::pair{10.8, 5.1}, std::pair{11.0, 6.0}, std::pair{3.37, 7.93}}) {
    std::vector<Deposit> ds;
    splat_tent(x, y, 2.0, {1.0f, 1.0f, 1.0f}, 20, 12, {}, ds);
    EXPECT_EQ(ds.size(), 4u);
    const Sum s = summed(ds);
    EXPECT_NEAR(s.light, 2.0, 1e-6) << x << "," << y;
    EXPECT_NEAR(s.x, x, 1e-6) << x << "," << y;
    EXPECT_NEAR(s.y, y, 1e-6) << x << "," << y;
    for (const Deposit& d : ds) {
      EXPECT_LE(std::abs(d.i + 0.5 - x), 1.0);
      EXPECT_LE(std::abs(d.j + 0.5 - y), 1.0);
    }
  }
  std::vector<Deposit> centre;
  splat_tent(10.5, 5.5, 1.0, {1.0f, 2.0f, 3.0f}, 20, 12, {}, centre);
  for (const Deposit& d : centre)
    if (d.i != 10 || d.j != 5) {
      EXPECT_EQ(d.flux[0], 0.0f);
    }
  std::vector<Deposit> edge;
  splat_tent(0.2, 5.5, 1.0, {1.0f, 1.0f, 1.0f}, 20, 12, {}, edge);
  EXPECT_NEAR(summed(edge).light, 0.7, 1e-6);
}

// Where the image wraps, nothing is lost at its edges: the share beyond
// the left or right edge lands across the seam, the share above the top
// row (below the bottom one) on that row half a turn away.
TEST(PixelDeposits, WhereTheImageWrapsTheFilterReachesAcrossTheEdge) {
  const ImageWrap wrap{true, true};
  std::vector<Deposit> seam, pole;
  splat_tent(0.2, 5.5, 1.0, {1.0f, 1.0f, 1.0f}, 20, 12, wrap, seam);
  ASSERT_EQ(seam.size(), 4u);  // two of them with no weight (y on a row's centre)
  double total = 0, at_last = 0;
  for (const Deposit& d : seam) {
    total += d.flux[0];
    if (d.i == 19) at_last += d.flux[0];
    EXPECT_TRUE(d.i == 19 || d.i == 0) << d.i;
  }
  EXPECT_NEAR(total, 1.0, 1e-6);
  EXPECT_NEAR(at_last, 0.3, 1e-6);
  splat_tent(3.5, 0.1, 1.0, {1.0f, 1.0f, 1.0f}, 20, 12, wrap, pole);
  total = 0;
  double over = 0;
  for (const Deposit& d : pole) {
    total += d.flux[0];
    EXPECT_EQ(d.j, 0);
    if (d.i == 13) over += d.flux[0];  // column 3 half a turn away
  }
  EXPECT_NEAR(total, 1.0, 1e-6);
  EXPECT_NEAR(over, 0.4, 1e-6);
}

TEST(PixelDeposits, DepositsOnOnePixelSum) {
  std::vector<Deposit> ds = {{3, 2, {1, 0, 0}}, {1, 4, {0, 1, 0}}, {3, 2, {0.5f, 0, 2}}, {0, 2, {1, 1, 1}}};
  sum_deposits_per_pixel(ds);
  ASSERT_EQ(ds.size(), 3u);
  EXPECT_EQ(ds[0].i, 0);
  EXPECT_EQ(ds[1].i, 3);
  EXPECT_EQ(ds[1].j, 2);
  EXPECT_EQ(ds[1].flux[0], 1.5f);
  EXPECT_EQ(ds[1].flux[2], 2.0f);
  EXPECT_EQ(ds[2].j, 4);
}

TEST(PixelLight, RadianceTimesThePixelsSolidAngleIsTheFluxAndGlareKeepsIt) {
  const test::Pinhole cam{24, 16, 30};
  const CameraDirections camera = [&](double x, double y) { return cam.at(x, y); };
  const std::vector<Deposit> ds = {{5, 3, {1, 1, 1}}, {12, 8, {2, 2, 2}}};
  const GlareKernel kernel(1.5);
  double within = 0.0;
  for (const double w : kernel.weight) within += w;
  EXPECT_NEAR(within, 1.0, 1e-12);
  EXPECT_NEAR(kernel.within[static_cast<std::size_t>(kernel.radius)], 1.0, 1e-12);
  for (const GlareSpread spread : {GlareSpread{}, GlareSpread{&kernel, 0.3, 1e-3, 1.0}}) {
    double cpu = 0.0;
    const std::vector<LitPixel> lit = light_pixels(ds, camera, spread, 2, cpu);
    ASSERT_EQ(lit.size(), 2u);
    std::vector<float> rgb(3 * 24 * 16, 0.0f);
    add_lit_pixels(ds, lit, spread, 24, 16, 5, 3, rgb, cpu);
    double total = 0.0;
    int pixels = 0;
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 24; ++i)
        if (const float r = rgb[3 * static_cast<std::size_t>(j * 24 + i)]; r > 0) {
          // The halo's pixels are taken as the lit one's size: 1% here.
          total += r * cam.pixel_solid_angle(i, j);
          ++pixels;
        }
    EXPECT_NEAR(total, 3.0, spread.kernel ? 0.03 : 1e-6);
    if (!spread.kernel) {
      EXPECT_NEAR(lit[0].radiance[0] * cam.pixel_solid_angle(5, 3), 1.0, 1e-6);
      EXPECT_EQ(pixels, 2);
    } else {
      EXPECT_GT(pixels, 18);  // at least the 3 x 3 around each
    }
  }
}

}  // namespace
}  // namespace lc
