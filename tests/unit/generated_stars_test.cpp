// Tests of the procedural star field: deterministic per seed, a plausible
// number of stars with many more faint than bright ones and only a slight
// tint, stars round on the sphere (wider in the image near the poles), and
// errors naming the file.

#include <gtest/gtest.h>

#include "scratch_dir.hpp"
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image.hpp"

namespace {

namespace fs = std::filesystem;
using lc::FrameImage;
using lc::Star;
constexpr double kPi = std::numbers::pi;

using lc::test::ScratchDir;

std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

double luminance(const FrameImage& im, int i, int j) {
  const float* p =
      &im.rgb[3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(im.width) + static_cast<std::size_t>(i))];
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

TEST(GeneratedStars, SameSeedSameBytesOtherSeedOtherSky) {
  ScratchDir dir;
  lc::make_starfield(dir / "a.png", 64, 32, 7);
  lc::make_starfield(dir / "b.png", 64, 32, 7);
  lc::make_starfield(dir / "c.png", 64, 32, 8);
  const std::string a = file_bytes(dir / "a.png");
  EXPECT_GT(a.size(), 100u);
  EXPECT_EQ(a, file_bytes(dir / "b.png"));
  EXPECT_NE(a, file_bytes(dir / "c.png"));

  // An 8-bit sRGB PNG a texture can use.
  const lc::Texture t = lc::Texture::load(dir / "a.png");
  EXPECT_EQ(t.width(), 64);
  EXPECT_EQ(t.height(), 32);
}

TEST(GeneratedStars, CatalogueHasAFewThousandStarsMostlyFaintSlightlyTinted) {
  const std::vector<Star> stars = lc::starfield_catalogue(1);
  ASSERT_GE(stars.size(), 2000u);
  ASSERT_LE(stars.size(), 10000u);
  double faintest = 1e30;
  for (const Star& s : stars) faintest = std::min(faintest, s.peak);
  std::size_t above2 = 0, above8 = 0, tinted = 0, north = 0;
  for (const Star& s : stars) {
    const double norm = std::hypot(s.direction[0], s.direction[1], s.direction[2]);
    EXPECT_NEAR(norm, 1.0, 1e-12);
    EXPECT_GT(s.sigma, 0.0);
    above2 += s.peak > 2 * faintest;
    above8 += s.peak > 8 * faintest;
    north += s.direction[2] > 0;
    const float lo = std::min({s.tint[0], s.tint[1], s.tint[2]}), hi = std::max({s.tint[0], s.tint[1], s.tint[2]});
    EXPECT_GT(lo, 0.3f);
    EXPECT_LT(hi / lo, 2.5f);  // slight colour, never saturated
    tinted += hi / lo > 1.1f;
    EXPECT_NEAR(0.2126 * s.tint[0] + 0.7152 * s.tint[1] + 0.0722 * s.tint[2], 1.0, 0.05);
  }
  const double n = static_cast<double>(stars.size());
  // Brightness N(> P) ∝ P^-1.5: 2^-1.5 = 0.354 and 8^-1.5 = 0.044 of all.
  EXPECT_NEAR(above2 / n, 0.354, 0.04);
  EXPECT_NEAR(above8 / n, 0.044, 0.015);
  EXPECT_GT(tinted / n, 0.3);        // colours vary...
  EXPECT_NEAR(north / n, 0.5, 0.1);  // ...and stars cover both hemispheres
  // A different seed is a different sky.
  EXPECT_NE(lc::starfield_catalogue(2)[0].direction, stars[0].direction);
}

TEST(GeneratedStars, RenderedSkyIsDarkWithDistinctStars) {
  const FrameImage im = lc::render_starfield(256, 128, 1);
  ASSERT_EQ(im.rgb.size(), 3u * 256 * 128);
  std::vector<double> lum;
  for (int j = 0; j < im.height; ++j)
    for (int i = 0; i < im.width; ++i) lum.push_back(luminance(im, i, j));
  std::vector<double> sorted = lum;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  EXPECT_GT(median, 1e-4);  // not pitch black...
  EXPECT_LT(median, 3e-3);  // ...but a night sky (sRGB code < 10)

  // Stars: local maxima (8 neighbours, u periodic) well above the median.
  int faint = 0, bright = 0;
  float brightest = 0.0f;
  for (int j = 1; j + 1 < im.height; ++j)
    for (int i = 0; i < im.width; ++i) {
      const double v = lum[static_cast<std::size_t>(j * im.width + i)];
      bool peak = true;
      for (int dj = -1; dj <= 1 && peak; ++dj)
        for (int di = -1; di <= 1 && peak; ++di)
          if ((di != 0 || dj != 0) &&
              lum[static_cast<std::size_t>((j + dj) * im.width + (i + di + im.width) % im.width)] >= v)
            peak = false;
      if (!peak) continue;
      faint += v > median + 0.01;
      bright += v > median + 0.1;
      brightest = std::max(brightest, static_cast<float>(v));
    }
  EXPECT_GE(faint, 30);
  EXPECT_LE(faint, 1000);
  EXPECT_GE(bright, 2);
  EXPECT_LT(bright * 3, faint);
  EXPECT_GT(brightest, 0.15f);
}

// Second moments (radians²) of the light one star added to an image, on
// the tangent plane at the star (theta0, phi0): along the meridian and
// along the parallel.  Each texel counts with its solid angle (∝ sin θ).
std::array<double, 2> moments(const FrameImage& im, double theta0, double phi0) {
  const std::array<double, 3> e_theta = {std::cos(theta0) * std::cos(phi0), std::cos(theta0) * std::sin(phi0),
                                         -std::sin(theta0)};
  const std::array<double, 3> e_phi = {-std::sin(phi0), std::cos(phi0), 0.0};
  double m_theta = 0.0, m_phi = 0.0, sum = 0.0;
  for (int j = 0; j < im.height; ++j)
    for (int i = 0; i < im.width; ++i) {
      const double theta = kPi * (j + 0.5) / im.height, phi = 2 * kPi * (i + 0.5) / im.width;
      const std::array<double, 3> d = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                                       std::cos(theta)};
      const double x = d[0] * e_phi[0] + d[1] * e_phi[1] + d[2] * e_phi[2];
      const double y = d[0] * e_theta[0] + d[1] * e_theta[1] + d[2] * e_theta[2];
      const double w = luminance(im, i, j) * std::sin(theta);
      m_theta += w * y * y;
      m_phi += w * x * x;
      sum += w;
    }
  return {m_theta / sum, m_phi / sum};
}

FrameImage black(int w, int h) {
  FrameImage im;
  im.width = w;
  im.height = h;
  im.rgb.assign(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
  return im;
}

TEST(GeneratedStars, StarsAreRoundOnTheSphereAndWiderNearThePoles) {
  const double texel = kPi / 64;  // of a 128 x 64 image
  // 1.5 texels: footprints bounded in longitude; 3 texels: the caps near
  // the poles reach them and take whole rows.
  for (double sigma : {1.5 * texel, 3.0 * texel})
    for (double theta0 : {kPi / 2, 0.45, 2.6}) {
      const double phi0 = 1.0;
      const Star star{{std::sin(theta0) * std::cos(phi0), std::sin(theta0) * std::sin(phi0), std::cos(theta0)},
                      sigma,
                      1.0,
                      {1.0f, 1.0f, 1.0f}};
      FrameImage im = black(128, 64);
      lc::add_stars(im, std::span<const Star>(&star, 1));
      const std::array<double, 2> m = moments(im, theta0, phi0);
      EXPECT_NEAR(m[1] / m[0], 1.0, 0.05) << "theta " << theta0 << " sigma " << sigma;  // round on the sphere
      EXPECT_NEAR(std::sqrt(m[0]), std::hypot(sigma, 0.5 * texel), 0.1 * sigma);        // flux-kept blur

      // In texels the footprint is 1 / sin θ wider along the row than at the
      // equator (the limit for stars much smaller than their distance θ
      // from the pole, so only for the smaller one).
      if (theta0 == kPi / 2 || sigma > 2 * texel) continue;
      const Star on_equator{{std::cos(phi0), std::sin(phi0), 0.0}, sigma, 1.0, {1.0f, 1.0f, 1.0f}};
      FrameImage eq = black(128, 64);
      lc::add_stars(eq, std::span<const Star>(&on_equator, 1));
      const int row = static_cast<int>(theta0 / kPi * 64);
      const double row_theta = kPi * (row + 0.5) / 64;
      double width_row = 0.0, width_eq = 0.0;  // luminance-weighted spread in texels
      for (int i = 0; i < 128; ++i) {
        const double di = i + 0.5 - phi0 / (2 * kPi) * 128;
        width_row += luminance(im, i, row) * di * di;
        width_eq += luminance(eq, i, 32) * di * di;
      }
      double sum_row = 0.0, sum_eq = 0.0;
      for (int i = 0; i < 128; ++i) {
        sum_row += luminance(im, i, row);
        sum_eq += luminance(eq, i, 32);
      }
      EXPECT_NEAR(std::sqrt(width_row / sum_row) / std::sqrt(width_eq / sum_eq), 1.0 / std::sin(row_theta), 0.25)
          << "theta " << theta0 << " sigma " << sigma;
    }

  // A star on the pole lights its ring of texels evenly.
  FrameImage im = black(128, 64);
  const Star pole{{0.0, 0.0, 1.0}, 3.0 * texel, 1.0, {1.0f, 1.0f, 1.0f}};
  lc::add_stars(im, std::span<const Star>(&pole, 1));
  for (int i = 1; i < 128; ++i) EXPECT_NEAR(luminance(im, i, 0), luminance(im, 0, 0), 1e-6);
  EXPECT_GT(luminance(im, 0, 0), 0.1);
}

TEST(GeneratedStars, BadSizeThrowsNamingTheFile) {
  ScratchDir dir;
  const fs::path file = dir / "sky.png";
  for (auto [w, h] : {std::array<int, 2>{0, 16}, {32, -1}, {40000, 20000}}) {
    try {
      lc::make_starfield(file, w, h, 1);
      ADD_FAILURE() << "no error for " << w << " x " << h;
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(fs::exists(file));
}

}  // namespace
