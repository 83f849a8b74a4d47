// A frame's look (image/look.hpp): the paper's look leaves the light
// alone, the standard and filmic views are the per-channel curves they
// always were (so those frames' PNGs do not change), and a graded look
// exposes, blooms, balances and saturates before its view.

#include <gtest/gtest.h>

#include <cmath>

#include "image/look.hpp"

namespace lc {
namespace {

FrameImage frame_of(std::vector<float> rgb, int width) {
  return FrameImage{width, static_cast<int>(rgb.size() / 3 / width), std::move(rgb), {}, {}, {}};
}

TEST(Look, ThePapersLookIsTheLightAsItIs) {
  const Look none;
  EXPECT_TRUE(none.identity());
  const FrameImage f{2, 1, {0.3f, 7.0f, -0.5f, 0.0f, 1.0f, 2.0f}, {{"hit.r", {1.0f, 2.0f}}}, {}, {1.0f, 0.5f}};
  const FrameImage d = none.applied(f);
  EXPECT_EQ(d.rgb, f.rgb);  // clipping is the sRGB encoder's
  EXPECT_EQ(d.alpha, f.alpha);
  EXPECT_TRUE(d.layers.empty());
}

TEST(Look, ExposureAndTheFilmicViewAreTheCurvesTheyWere) {
  // x 2^exposure in double, then the curve, rounded to float once.
  const Look darker{.exposure = -1.0};
  EXPECT_FALSE(darker.identity());
  EXPECT_EQ(darker.applied(frame_of({0.5f, 3.0f, 0.1f}, 1)).rgb, (std::vector<float>{0.25f, 1.5f, 0.05f}));
  const Look filmic{.exposure = 0.5, .view = View::filmic};
  const std::vector<float> in = {0.2f, 1.0f, 40.0f, -1.0f, 0.0f, 3.0f};
  const FrameImage out = filmic.applied(frame_of(in, 2));
  for (std::size_t k = 0; k < in.size(); ++k)
    EXPECT_EQ(out.rgb[k], static_cast<float>(filmic_curve(in[k] * std::exp2(0.5)))) << k;
}

TEST(Look, GamutSafeViewActsPerPixel) {
  const Look safe{.exposure = 1.0, .view = View::gamut_safe};
  const FrameImage out = safe.applied(frame_of({0.2f, 0.1f, 0.05f, -0.2f, 0.3f, 2.0f}, 2));
  const auto a = gamut_safe_view({0.4, 0.2, 0.1});
  const auto b = gamut_safe_view({-0.4, 0.6, 4.0});
  for (int i = 0; i < 3; ++i) {
    EXPECT_FLOAT_EQ(out.rgb[static_cast<std::size_t>(i)], static_cast<float>(a[static_cast<std::size_t>(i)]));
    EXPECT_FLOAT_EQ(out.rgb[static_cast<std::size_t>(3 + i)], static_cast<float>(b[static_cast<std::size_t>(i)]));
  }
}

TEST(Look, AGradeActsOnTheExposedLightBeforeTheView) {
  // Saturation 0 makes grey of the exposed light's luminance; white balance
  // at a blackbody's temperature turns its colour grey (grade.hpp); bloom's
  // threshold is the exposed light's 1: a pixel at 0.6 blooms at +1 stop and
  // not at 0, and the frame's light is kept (1e-5: float sums).
  const Look grey{.exposure = 1.0, .saturation = 0.0};
  const FrameImage g = grey.applied(frame_of({0.3f, 0.1f, 0.05f}, 1));
  const float y = static_cast<float>(2.0 * (0.2126 * 0.3 + 0.7152 * 0.1 + 0.0722 * 0.05));
  for (float v : g.rgb) EXPECT_NEAR(v, y, 1e-6);
  std::vector<float> dim(3 * 9 * 9, 0.0f);
  for (int c = 0; c < 3; ++c) dim[3 * 40 + static_cast<std::size_t>(c)] = 0.6f;
  const Look no_bloom_at_zero{.bloom = 1.0, .bloom_radius = 0.1};
  EXPECT_EQ(no_bloom_at_zero.applied(frame_of(dim, 9)).rgb, dim);
  const Look bloom_at_one{.exposure = 1.0, .bloom = 1.0, .bloom_radius = 0.1};
  const FrameImage b = bloom_at_one.applied(frame_of(dim, 9));
  double sum = 0.0;
  for (float v : b.rgb) sum += v;
  EXPECT_NEAR(sum, 3 * 1.2, 1e-5);
  EXPECT_LT(b.rgb[3 * 40], 1.2f);  // light left the bright pixel ...
  EXPECT_GT(b.rgb[3 * 41], 0.0f);  // ... for its neighbours
}

TEST(Look, ItsTextReadsBackAsTheSameLookToTheBit) {
  EXPECT_EQ(look_text(Look{}), "");
  EXPECT_EQ(parse_look_text(""), Look{});
  // Numbers that decimal text rounds unless written in full.
  const Look look{-1.0 / 3.0, View::gamut_safe, 5000.0, 1.3, 0.25, 0.015};
  const std::string text = look_text(look);
  EXPECT_EQ(text, "exposure:-0.3333333333333333,view:gamut_safe,white_balance:5000,saturation:1.3,bloom:0.25,"
                  "bloom_radius:0.015");
  EXPECT_EQ(parse_look_text(text), look);
  // Only what differs from the paper's look is written.
  EXPECT_EQ(look_text(Look{.exposure = 2.0}), "exposure:2");
  EXPECT_EQ(look_text(Look{.view = View::filmic}), "view:filmic");
}

TEST(Look, ABadTextNamesThePartAtFault) {
  auto message = [](std::string_view text) {
    try {
      parse_look_text(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("view:agx").find("'view:agx': the view is standard, filmic or gamut_safe"), std::string::npos);
  EXPECT_NE(message("exposure:1,glow:2").find("'glow:2'"), std::string::npos);
  EXPECT_NE(message("exposure:high").find("high is not a number"), std::string::npos);
  EXPECT_NE(message("exposure:nan").find("not a number"), std::string::npos);
  EXPECT_NE(message("exposure").find("name:value"), std::string::npos);
}

}  // namespace
}  // namespace lc
