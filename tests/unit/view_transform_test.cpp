// The view transforms (image/view_transform.hpp): the filmic curve is
// Narkowicz's fit; the gamut_safe view shows luminance through a monotone
// curve and keeps each colour's hue while fading what does not fit towards
// white.  The sweep checks light a texture's grey turns into seen through
// every frequency ratio g the spectral table has.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "image/grade.hpp"
#include "image/srgb.hpp"
#include "image/view_transform.hpp"
#include "light/spectral_shift.hpp"

namespace lc {
namespace {

double luminance(const std::array<double, 3>& c) {
  return rec709_luminance[0] * c[0] + rec709_luminance[1] * c[1] + rec709_luminance[2] * c[2];
}
// Hue angle in the plane across the grey axis: adding grey leaves it alone.
double hue(const std::array<double, 3>& c) {
  return std::atan2(std::sqrt(3.0) * (c[1] - c[2]), 2.0 * c[0] - c[1] - c[2]);
}
double chroma(const std::array<double, 3>& c) {
  return std::hypot(std::sqrt(3.0) * (c[1] - c[2]), 2.0 * c[0] - c[1] - c[2]);
}
double hue_step(double a, double b) {
  double d = std::abs(a - b);
  return std::min(d, 2.0 * std::numbers::pi - d);
}

TEST(ViewTransform, FilmicCurveIsNarkowiczsFit) {
  EXPECT_EQ(filmic_curve(0.0), 0.0);
  EXPECT_EQ(filmic_curve(-1.0), 0.0);
  EXPECT_EQ(filmic_curve(std::nan("")), 0.0);
  EXPECT_NEAR(filmic_curve(1.0), 2.54 / 3.16, 1e-12);
  EXPECT_EQ(filmic_curve(1e6), 1.0);
}

TEST(ViewTransform, LuminanceCurveRisesTowardsOneWithoutReachingIt) {
  EXPECT_EQ(filmic_luminance_curve(0.0), 0.0);
  EXPECT_NEAR(filmic_luminance_curve(1.0), 2.54 / 3.16 * 2.43 / 2.51, 1e-12);
  double last = 0.0;
  for (double y = 1e-6; y < 1e6; y *= 1.05) {
    const double v = filmic_luminance_curve(y);
    EXPECT_GT(v, last) << y;
    EXPECT_LT(v, 1.0) << y;
    last = v;
  }
  EXPECT_GT(filmic_luminance_curve(1e6), 0.9999);
}

TEST(ViewTransform, KneeIsTheIdentityInsideAndApproachesOneOutside) {
  EXPECT_EQ(gamut_knee(0.5), 0.5);
  EXPECT_EQ(gamut_knee(0.8), 0.8);
  // C1 at the knee: its slope there is 1.
  EXPECT_NEAR((gamut_knee(0.8 + 1e-7) - 0.8) / 1e-7, 1.0, 1e-6);
  double last = 0.8;
  for (double d = 0.81; d < 1e6; d *= 1.1) {
    EXPECT_GT(gamut_knee(d), last) << d;
    EXPECT_LT(gamut_knee(d), 0.98) << d;
    last = gamut_knee(d);
  }
  EXPECT_GT(gamut_knee(1e9), 0.98 - 1e-9);
}

TEST(ViewTransform, GamutSafeKeepsLuminanceThroughTheCurveAndHue) {
  // Colours in and out of the gamut, dim and bright: every channel shown is
  // in [0, 1], the luminance shown is the curve's of the light's (1e-12:
  // rounding), and the hue is the light's wherever it has colour to speak
  // of (1e-9 rad).
  const std::array<std::array<double, 3>, 7> colours = {{{0.5, 0.5, 0.5},
                                                         {0.2, 0.05, 0.01},
                                                         {-0.3, 0.6, 1.4},
                                                         {3.0, 0.2, 0.1},
                                                         {0.0, 0.0, 40.0},
                                                         {1.0, -0.5, 0.2},
                                                         {1e5, 2e5, 3e4}}};
  for (const auto& c : colours)
    for (double scale : {0.01, 0.3, 1.0, 8.0, 500.0}) {
      const std::array<double, 3> light{c[0] * scale, c[1] * scale, c[2] * scale};
      const auto shown = gamut_safe_view(light);
      for (double v : shown) {
        EXPECT_GE(v, 0.0);
        EXPECT_LE(v, 1.0);
      }
      EXPECT_NEAR(luminance(shown), filmic_luminance_curve(luminance(light)), 1e-12) << c[0] << " x" << scale;
      if (chroma(shown) > 1e-6 * luminance(shown)) EXPECT_NEAR(hue_step(hue(shown), hue(light)), 0.0, 1e-9);
    }
  // No light, or light of negative luminance, shows black.
  EXPECT_EQ(gamut_safe_view({0.0, 0.0, 0.0}), (std::array<double, 3>{0.0, 0.0, 0.0}));
  EXPECT_EQ(gamut_safe_view({-1.0, 0.1, 0.0}), (std::array<double, 3>{0.0, 0.0, 0.0}));
  // Very bright light is white, whatever its colour.
  const auto white = gamut_safe_view({1e12, 0.0, 0.0});
  for (double v : white) EXPECT_NEAR(v, 1.0, 1e-6);
}

// A grey texel seen through g from 0.4 to 2.5 (the colour shift with the
// beaming, light_models.lua's "both"), at three exposures.  The light's own
// luminance rises from black (its bands below the visible) to a peak and
// falls to black again (above it), so "monotone" means: the luminance shown
// moves with the light's at every step, never against it.  The hue shown is
// the light's, and moves in steps no larger than the light's.  No sample is
// a flat clipped patch (a channel at 8-bit 0 while another is above 128),
// which the per-channel filmic curve on the same light makes.
TEST(ViewTransform, GreySeenThroughEveryGMovesSmoothly) {
  const SpectralShift table;
  for (double exposure : {-1.0, 0.0, 2.0}) {
    const double scale = std::exp2(exposure);
    const int steps = 800;
    std::array<double, 3> last_light{}, last_shown{};
    int flat_gamut_safe = 0, flat_filmic = 0;
    double largest_hue_step = 0.0;
    for (int k = 0; k <= steps; ++k) {
      const double g = SpectralShift::g_min * std::pow(SpectralShift::g_max / SpectralShift::g_min, double(k) / steps);
      const Color seen = table({0.5f, 0.5f, 0.5f}, g);
      const std::array<double, 3> light{seen[0] * scale, seen[1] * scale, seen[2] * scale};
      const auto shown = gamut_safe_view(light);
      const auto flat = [](const std::array<double, 3>& d) {
        int zero = 0, bright = 0;
        for (double v : d) {
          zero += linear_to_srgb8(static_cast<float>(v)) == 0;
          bright += linear_to_srgb8(static_cast<float>(v)) > 128;
        }
        return zero > 0 && bright > 0;
      };
      flat_gamut_safe += flat(shown);
      flat_filmic += flat({filmic_curve(light[0]), filmic_curve(light[1]), filmic_curve(light[2])});
      if (k > 0) {
        const double d_light = luminance(light) - luminance(last_light);
        const double d_shown = luminance(shown) - luminance(last_shown);
        if (std::abs(d_light) > 1e-12 * luminance(light))
          EXPECT_GT(d_light * d_shown, 0.0) << "g " << g << " exposure " << exposure;
        // Hue is ill-conditioned near grey (the sweep passes grey at g = 1),
        // so it is compared where the colour is clearly coloured; everywhere
        // the colour shown moves continuously.
        const bool coloured = chroma(shown) > 0.2 * luminance(shown) && chroma(last_shown) > 0.2 * luminance(last_shown);
        // (0.1 a step of 0.23% in g: the steepest stretch, g = 1.38 at +2
        // stops, is blue light beyond the display's blue primary whose
        // luminance, a small difference of channels, falls 3.6% a step.)
        for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(shown[i] - last_shown[i]), 0.1) << "g " << g;
        // Where the light is visible at all (the hue of light fading to
        // black as its last band leaves the visible turns fast: its own).
        if (coloured && linear_to_srgb8(static_cast<float>(luminance(shown))) > 2 &&
            linear_to_srgb8(static_cast<float>(luminance(last_shown))) > 2) {
          const double step = hue_step(hue(shown), hue(last_shown));
          EXPECT_LE(step, hue_step(hue(light), hue(last_light)) + 1e-9) << "g " << g;
          largest_hue_step = std::max(largest_hue_step, step);
        }
      }
      last_light = light;
      last_shown = shown;
    }
    EXPECT_EQ(flat_gamut_safe, 0) << "exposure " << exposure;
    EXPECT_GT(flat_filmic, 0) << "exposure " << exposure << ": the sweep no longer reaches out of the gamut";
    // No flip: the light's own hue turns by up to 15 degrees in a step
    // where a band crosses a channel's edge, and the shown hue never turns
    // more than the light's (above).
    EXPECT_LT(largest_hue_step, 20.0 * std::numbers::pi / 180.0) << "exposure " << exposure;
  }
}

TEST(ViewTransform, AFrameAtOnceIsEveryPixelByItself) {
  // show_gamut_safe computes four pixels at a time: its floats must be
  // gamut_safe_view's, bit for bit, for colours of every kind (dark, inside
  // the gamut, saturated beyond it, far above white, negative, exactly
  // grey, black, NaN and infinite) and for a frame not a multiple of four.
  std::mt19937 random(29);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<float> rgb;
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const std::vector<std::array<float, 3>> special = {
      {0, 0, 0}, {1, 1, 1}, {0.5f, 0.5f, 0.5f}, {-1, 0.1f, 0}, {1e30f, 0, 0}, {nan, 0.2f, 0.1f}, {inf, 1, 1},
      {0.2f, -0.05f, 0.9f}, {3e-39f, 0, 0}, {0, 0, 5}, {-0.0f, 0.0f, 0.3f}};
  for (const auto& c : special) rgb.insert(rgb.end(), c.begin(), c.end());
  for (int p = 0; p < 40001; ++p) {
    const float scale = std::exp2(unit(random) * 24.0f - 12.0f);  // 2^-12 to 2^12
    for (int i = 0; i < 3; ++i) rgb.push_back(scale * (unit(random) * 1.2f - 0.1f));
  }
  for (const double exposure : {1.0, 0.37, 8.0}) {
    std::vector<float> batch = rgb;
    show_gamut_safe(batch, exposure);
    std::size_t differing = 0;
    for (std::size_t p = 0; p < rgb.size(); p += 3) {
      const auto one = gamut_safe_view({rgb[p] * exposure, rgb[p + 1] * exposure, rgb[p + 2] * exposure});
      for (int i = 0; i < 3; ++i) {
        const float expected = static_cast<float>(one[static_cast<std::size_t>(i)]);
        differing += std::memcmp(&expected, &batch[p + static_cast<std::size_t>(i)], sizeof(float)) != 0;
      }
    }
    EXPECT_EQ(differing, 0u) << "exposure " << exposure;
  }
}

}  // namespace
}  // namespace lc
