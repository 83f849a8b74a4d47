// The grade's operations against what they promise: white balance makes a
// blackbody's light grey at its luminance, by the Bradford transform, and is
// the identity for D65 itself; saturation keeps each pixel's luminance;
// bloom moves light without losing any, only light above its threshold, into
// a symmetric Gaussian glow.  Frames are floats, so what is kept through them
// is asked to float rounding (~6e-8 relative per value); what is computed in
// double before any float, to double rounding.

#include "image/grade.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>

#include <fmt/format.h>

#include "light/blackbody.hpp"
#include "test_errors.hpp"

namespace lc {
namespace {

std::array<double, 3> times(const Mat3& m, const std::array<double, 3>& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

double largest_difference_from_identity(const Mat3& m) {
  double d = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d = std::max(d, std::abs(m[i][j] - (i == j ? 1.0 : 0.0)));
  return d;
}

double luminance(const float* c) {
  return rec709_luminance[0] * c[0] + rec709_luminance[1] * c[1] + rec709_luminance[2] * c[2];
}

bool same_bytes(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// D65's own white adapts to itself: the diagonal scaling is 1 up to double
// rounding, so the product of the five matrices is the identity to 1e-12.
TEST(WhiteBalance, DaylightsOwnWhiteIsTheIdentity) {
  const XYZ d65 = srgb_white_xyz();
  EXPECT_EQ(d65.Y, 1.0);
  const double s = d65.X + d65.Y + d65.Z;
  EXPECT_LT(largest_difference_from_identity(white_balance_matrix_from_xy(d65.X / s, d65.Y / s)), 1e-12);
  // The white the code's XYZ -> sRGB matrix encodes is IEC 61966-2-1's D65,
  // (0.3127, 0.3290), to the matrix's 4-digit rounding (measured: 1.6e-5
  // in x, 2.6e-6 in y), so adapting from the rounded chromaticity is the
  // identity only to that: measured 1.3e-4.
  EXPECT_NEAR(d65.X / s, 0.3127, 3e-5);
  EXPECT_NEAR(d65.Y / s, 0.3290, 3e-5);
  EXPECT_LT(largest_difference_from_identity(white_balance_matrix_from_xy(0.3127, 0.3290)), 3e-4);
}

// D65's correlated colour temperature is 6504 K, but D65 lies off the
// Planckian locus (Δuv ≈ 0.003, above it: greener), so the blackbody at
// 6504 K is not D65's white and its balance is near, not at, the identity.
// Its chromaticity here, (0.3134, 0.3237), is the locus's (Wyszecki &
// Stiles) to the colour-matching fit's ~1e-4, so the gap is D65's, not the
// fit's.  Measured: the largest entry off the identity by 3.0e-2 (blue's
// diagonal 0.970, red's 0.987, green's 1.014): green raised against red and
// blue, undoing the Planckian light's magenta relative to daylight.  Not the
// ~2e-3 one might hope for from "D65 is 6504 K".
TEST(WhiteBalance, AtDaylightsTemperatureNearlyTheIdentity) {
  const Mat3 m = white_balance_matrix(6504.0);
  EXPECT_LT(largest_difference_from_identity(m), 3.5e-2);
  EXPECT_GT(largest_difference_from_identity(m), 2e-2) << "the Planckian locus misses D65: not the identity";
  EXPECT_GT(m[1][1], 1.0);
  EXPECT_LT(m[2][2], 1.0);
  // Far from 6504 K the balance is strong: 3000 K light is warm, so red is
  // scaled down and blue up.
  const Mat3 warm = white_balance_matrix(3000.0);
  const auto red = times(warm, {1.0, 0.0, 0.0}), blue = times(warm, {0.0, 0.0, 1.0});
  EXPECT_LT(red[0], 0.8);
  EXPECT_GT(blue[2], 1.5);
}

// The point of the balance: light of the blackbody's colour comes out grey,
// D65 white at the blackbody's own luminance Y.  All in double: to 1e-9
// relative (the rounding of a few 3x3 products is ~1e-15).
TEST(WhiteBalance, TheBlackbodysLightBecomesGreyOfTheSameLuminance) {
  const auto grey = linear_srgb_exact(srgb_white_xyz());  // D65 at Y = 1
  EXPECT_NEAR(grey[0], grey[1], 1e-12);
  EXPECT_NEAR(grey[0], grey[2], 1e-12);
  for (const double T : {3000.0, 9600.0, 20000.0, 1000.0, 40000.0}) {
    const XYZ c = blackbody_xyz(T);
    const auto out = times(white_balance_matrix(T), linear_srgb_exact(c));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], out[0], 1e-9 * out[0]) << T << " K, channel " << i;
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], c.Y * grey[i], 1e-9 * c.Y) << T << " K, channel " << i;
    // Rec. 709's weights are the exact Y row of sRGB -> XYZ; the code's
    // rounded matrix agrees with them to ~1e-4, so its grey does too.
    const double y709 = rec709_luminance[0] * out[0] + rec709_luminance[1] * out[1] + rec709_luminance[2] * out[2];
    EXPECT_NEAR(y709, c.Y, 3e-4 * c.Y) << T << " K";
  }
}

TEST(WhiteBalance, TemperaturesOutOfRangeAreRefusedByName) {
  for (const double T : {999.5, 40001.0, -3.0}) {
    const std::string e = test::error_of<std::invalid_argument>([&] { white_balance_matrix(T); });
    EXPECT_NE(e.find(fmt::format("{}", T)), std::string::npos) << e;
  }
  EXPECT_NE(test::error_of<std::invalid_argument>([] { white_balance_matrix(std::nan("")); }).find("nan"),
            std::string::npos);
  EXPECT_NO_THROW(white_balance_matrix(1000.0));
  EXPECT_NO_THROW(white_balance_matrix(40000.0));
  EXPECT_THROW(white_balance_matrix_from_xy(0.3, 0.0), std::invalid_argument);
}

// apply_matrix is m times each pixel, negative components included, rounded
// once to float: equal to the double product to float rounding (1e-7
// relative of the pixel's largest magnitude).
TEST(WhiteBalance, AppliedToEveryPixelWithNegativeLightPassingThrough) {
  const Mat3 m = white_balance_matrix(3000.0);
  std::vector<float> rgb = {1.0f, 0.5f, 0.25f, -0.2f, 0.7f, 1.3f, 0.0f, 0.0f, 0.0f, 1e4f, -3.0f, 2.0f};
  const std::vector<float> before = rgb;
  apply_matrix(rgb, m);
  for (std::size_t p = 0; p < before.size(); p += 3) {
    const auto want = times(m, {before[p], before[p + 1], before[p + 2]});
    const double scale = std::max({std::abs(want[0]), std::abs(want[1]), std::abs(want[2]), 1e-30});
    for (int c = 0; c < 3; ++c) {
      EXPECT_TRUE(std::isfinite(rgb[p + c]));
      EXPECT_NEAR(rgb[p + c], want[c], 1e-7 * scale) << "pixel " << p / 3 << " channel " << c;
    }
  }
  std::vector<float> ragged(4, 1.0f);
  EXPECT_THROW(apply_matrix(ragged, m), std::invalid_argument);
}

std::vector<float> test_colours() {
  return {1.0f, 0.5f, 0.25f, 0.2f, 0.7f, 0.1f, 3.0f, 0.01f, 12.0f, 0.0f, 0.0f, 0.0f, 0.5f, 0.5f, 0.5f,
          -0.2f, 0.6f, 0.3f, 0.9f, -0.05f, 0.4f};
}

// s = 0: every component becomes Y, computed in double and rounded once, so
// r = g = b exactly and each equals Y to float rounding.
TEST(Saturation, ZeroGivesGreyOfTheSameLuminance) {
  std::vector<float> rgb = test_colours();
  const std::vector<float> before = rgb;
  apply_saturation(rgb, 0.0);
  for (std::size_t p = 0; p < rgb.size(); p += 3) {
    EXPECT_EQ(rgb[p], rgb[p + 1]);
    EXPECT_EQ(rgb[p], rgb[p + 2]);
    EXPECT_EQ(rgb[p], static_cast<float>(luminance(&before[p])));
  }
}

// s = 1 returns before touching anything: even -0 and NaN keep their bits.
TEST(Saturation, OneLeavesTheBytes) {
  std::vector<float> rgb = test_colours();
  rgb.insert(rgb.end(), {-0.0f, std::numeric_limits<float>::quiet_NaN(), 1e-40f});
  const std::vector<float> before = rgb;
  apply_saturation(rgb, 1.0);
  EXPECT_TRUE(same_bytes(rgb, before));
}

// Luminance is linear with weights summing to 1, so it is kept exactly in
// double; each stored component then rounds (6e-8 of itself) and s = 2
// doubles the deviations, so Y is asked to 1e-6 of the pixel's summed
// magnitude (Y itself can be small where components cancel).
TEST(Saturation, KeepsEveryPixelsLuminanceAndPassesNegativeLight) {
  for (const double s : {2.0, 0.5, 0.0, 7.0}) {
    std::vector<float> rgb = test_colours();
    const std::vector<float> before = rgb;
    apply_saturation(rgb, s);
    for (std::size_t p = 0; p < rgb.size(); p += 3) {
      const double size = std::abs(before[p]) + std::abs(before[p + 1]) + std::abs(before[p + 2]);
      EXPECT_NEAR(luminance(&rgb[p]), luminance(&before[p]), 1e-6 * size) << "s " << s << ", pixel " << p / 3;
      for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(rgb[p + c])) << "s " << s << ", pixel " << p / 3;
    }
  }
  // s = 2 pushes each component away from Y: the pixel (-0.2, 0.6, 0.3) of
  // luminance ~0.424 gets a more negative red.
  std::vector<float> rgb = {-0.2f, 0.6f, 0.3f};
  apply_saturation(rgb, 2.0);
  EXPECT_LT(rgb[0], -0.2f);
  EXPECT_THROW(apply_saturation(rgb, -0.1), std::invalid_argument);
}

// Random light in [0, 2) over a 64x48 frame (much of it above the
// threshold of 1) with a bright 3x3 spot in the top-left corner.
std::vector<float> busy_frame(int width, int height) {
  std::mt19937 gen(20240611);
  std::uniform_real_distribution<float> light(0.0f, 2.0f);
  std::vector<float> rgb(static_cast<std::size_t>(width) * height * 3);
  for (float& v : rgb) v = light(gen);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 3; ++c) rgb[(y * width + x) * 3 + c] = 50.0f + 10.0f * c;
  return rgb;
}

std::array<double, 3> channel_sums(const std::vector<float>& rgb) {
  std::array<double, 3> s{};
  for (std::size_t i = 0; i < rgb.size(); ++i) s[i % 3] += rgb[i];
  return s;
}

TEST(Bloom, StrengthZeroLeavesTheBytes) {
  std::vector<float> rgb = busy_frame(64, 48);
  const std::vector<float> before = rgb;
  apply_bloom(rgb, 64, 48, Bloom{0.0, 0.05, 0.5});
  EXPECT_TRUE(same_bytes(rgb, before));
}

// The sum over the frame of every channel is what it was: each blur pass is
// normalised per source pixel over the targets in the frame, so the sums are
// kept in double; storing the 3072 pixels as float rounds each by ~6e-8 of
// itself, so 1e-5 relative bounds the change with room.  From a glow
// smaller than a pixel to one larger than the frame (sigma 40 px), where
// most of the corner's glow would fall outside without the normalisation,
// and to one so wide (radius 1e6) that it spreads evenly.
TEST(Bloom, NoLightIsLostEvenFromTheCorner) {
  const int w = 64, h = 48;  // diagonal 80 px
  for (const double radius : {0.002, 0.05, 0.5, 1e6}) {
    std::vector<float> rgb = busy_frame(w, h);
    const auto before = channel_sums(rgb);
    const float corner = rgb[0];
    apply_bloom(rgb, w, h, Bloom{0.8, radius, 1.0});
    const auto after = channel_sums(rgb);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], before[c], 1e-5 * before[c]) << "radius " << radius;
    if (radius > 0.01) {
      EXPECT_LT(rgb[0], 0.5f * corner) << "the corner's light spread";
    }
  }
}

// Light below the threshold does not move, and at a small radius a bright
// pixel reaches only its kernel's 3.5 sigma: every pixel farther away keeps
// its bytes (nothing is added to it and nothing taken from it).
TEST(Bloom, DimPixelsAwayFromBrightOnesAreUnchanged) {
  const int w = 64, h = 48;
  std::mt19937 gen(7);
  std::uniform_real_distribution<float> dim(0.0f, 0.9f);
  std::vector<float> rgb(w * h * 3);
  for (float& v : rgb) v = dim(gen);
  for (int c = 0; c < 3; ++c) rgb[(10 * w + 10) * 3 + c] = 20.0f;
  const std::vector<float> before = rgb;
  const double radius = 0.0125;  // sigma 1 px: reach ceil(3.5) = 4 px
  apply_bloom(rgb, w, h, Bloom{1.0, radius, 1.0});
  int changed_near = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int i = (y * w + x) * 3;
      const bool near = std::abs(x - 10) <= 4 && std::abs(y - 10) <= 4;
      for (int c = 0; c < 3; ++c) {
        if (near)
          changed_near += rgb[i + c] != before[i + c];
        else
          EXPECT_EQ(std::memcmp(&rgb[i + c], &before[i + c], sizeof(float)), 0) << x << ", " << y;
      }
    }
  EXPECT_GT(changed_near, 0);
}

// One bright pixel in the middle of an odd-sized black frame: the glow is a
// separable Gaussian of sigma = radius x diagonal about it.  Mirror pixels
// are equal exactly (the kernel is built from k^2, and the other terms of
// each sum are zeros); the fall-off between neighbours is the Gaussian's,
// G(1)/G(2) = exp(1.5 / sigma^2), to float rounding (1e-5 relative).
TEST(Bloom, ASinglePixelGlowsSymmetrically) {
  const int w = 65, h = 49, cx = 32, cy = 24;
  std::vector<float> rgb(w * h * 3, 0.0f);
  const auto at = [&](int x, int y) { return rgb[(y * w + x) * 3 + 1]; };
  for (int c = 0; c < 3; ++c) rgb[(cy * w + cx) * 3 + c] = 10.0f;
  const double radius = 0.03, sigma = radius * std::hypot(w, h);  // ~2.4 px
  apply_bloom(rgb, w, h, Bloom{1.0, radius, 1.0});
  EXPECT_EQ(at(cx - 1, cy), at(cx + 1, cy));
  EXPECT_EQ(at(cx, cy - 1), at(cx, cy + 1));
  EXPECT_EQ(at(cx - 3, cy - 2), at(cx + 3, cy + 2));
  EXPECT_FLOAT_EQ(at(cx - 2, cy), at(cx, cy - 2)) << "round, not elliptical";
  EXPECT_GT(at(cx - 1, cy), 0.0f);
  EXPECT_NEAR(at(cx + 1, cy) / at(cx + 2, cy), std::exp(1.5 / (sigma * sigma)), 1e-5 * std::exp(1.5 / (sigma * sigma)));
  // The centre keeps its unbloomed tenth (threshold 1 of Y = 10) plus its
  // share of the glow: G(0)^2 of the normalised 2-D kernel.
  EXPECT_GT(at(cx, cy), 1.0f);
  EXPECT_LT(at(cx, cy), 10.0f);
  // Grey stays grey.
  EXPECT_EQ(rgb[((cy + 1) * w + cx) * 3], rgb[((cy + 1) * w + cx) * 3 + 2]);
}

// Only light above the threshold blooms: a uniform frame below it, or at
// it, keeps its bytes; and a frame of one pixel keeps its light (it has
// nowhere to go), to float rounding.
TEST(Bloom, LightBelowTheThresholdNeverBlooms) {
  for (const float level : {0.9f, 1.0f}) {
    std::vector<float> rgb(32 * 24 * 3, level);
    const std::vector<float> before = rgb;
    apply_bloom(rgb, 32, 24, Bloom{1.0, 0.1, 1.0});
    EXPECT_TRUE(same_bytes(rgb, before)) << level;
  }
  std::vector<float> one = {5.0f, 2.0f, 8.0f};
  apply_bloom(one, 1, 1, Bloom{1.0, 0.5, 1.0});
  EXPECT_FLOAT_EQ(one[0], 5.0f);
  EXPECT_FLOAT_EQ(one[1], 2.0f);
  EXPECT_FLOAT_EQ(one[2], 8.0f);
}

// Out-of-gamut light (a negative component) may bloom if its luminance is
// above the threshold; a pixel of luminance <= 0 never does.  Neither makes
// NaN.  Radius 0 is a glow of no width: nothing moves.
TEST(Bloom, NegativeLightAndZeroRadiusPassThrough) {
  const int w = 16, h = 12;
  std::vector<float> rgb(w * h * 3, 0.1f);
  const auto set = [&](int x, int y, std::array<float, 3> c) {
    for (int k = 0; k < 3; ++k) rgb[(y * w + x) * 3 + k] = c[k];
  };
  set(3, 3, {-0.5f, 4.0f, 0.2f});
  set(8, 6, {-2.0f, 0.1f, -1.0f});
  set(12, 9, {0.0f, 0.0f, 0.0f});
  const auto before = channel_sums(rgb);
  const std::vector<float> original = rgb;
  apply_bloom(rgb, w, h, Bloom{0.7, 0.1, 1.0});
  for (float v : rgb) EXPECT_TRUE(std::isfinite(v));
  const auto after = channel_sums(rgb);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(after[c], before[c], 1e-5 * std::abs(before[c]) + 1e-6);

  rgb = original;
  apply_bloom(rgb, w, h, Bloom{0.7, 0.0, 1.0});
  for (std::size_t i = 0; i < rgb.size(); ++i) EXPECT_FLOAT_EQ(rgb[i], original[i]) << i;
}

TEST(Bloom, RefusesAFrameOfTheWrongSizeAndBadSettings) {
  std::vector<float> rgb(10 * 10 * 3, 1.0f);
  EXPECT_NE(test::error_of<std::invalid_argument>([&] { apply_bloom(rgb, 10, 11, Bloom{0.5}); }).find("10x11"),
            std::string::npos);
  EXPECT_THROW(apply_bloom(rgb, -10, -10, Bloom{0.5}), std::invalid_argument);
  EXPECT_THROW(apply_bloom(rgb, 10, 10, Bloom{1.5}), std::invalid_argument);
  EXPECT_THROW(apply_bloom(rgb, 10, 10, Bloom{0.5, -0.1}), std::invalid_argument);
  EXPECT_THROW(apply_bloom(rgb, 10, 10, Bloom{0.5, 0.01, -1.0}), std::invalid_argument);
  EXPECT_THROW(apply_bloom(rgb, 10, 11, Bloom{0.0}), std::invalid_argument) << "size is checked even when off";
}

}  // namespace
}  // namespace lc
