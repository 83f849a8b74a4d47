// The display transform (image/display.hpp): the identity leaves the
// linear values alone, exposure scales by powers of two, and the filmic
// curve is Narkowicz's ACES fit: 0 at 0, 0.8038 at 1 (2.54 / 3.16),
// increasing, and never above 1.

#include <gtest/gtest.h>

#include "image/display.hpp"

namespace lc {
namespace {

TEST(Display, ExposureAndCurves) {
  const DisplayTransform none;
  EXPECT_TRUE(none.identity());
  EXPECT_EQ(none(0.3f), 0.3f);
  EXPECT_EQ(none(7.0f), 7.0f);  // clipping is the sRGB encoder's
  const DisplayTransform darker{-1.0, ToneCurve::clip};
  EXPECT_FALSE(darker.identity());
  EXPECT_FLOAT_EQ(darker(0.5f), 0.25f);
  const DisplayTransform filmic{0.0, ToneCurve::filmic};
  EXPECT_EQ(filmic(0.0f), 0.0f);
  EXPECT_EQ(filmic(-1.0f), 0.0f);
  EXPECT_NEAR(filmic(1.0f), 2.54 / 3.16, 1e-6);
  float last = 0.0f;
  for (float x = 0.01f; x < 100.0f; x *= 1.1f) {
    const float y = filmic(x);
    EXPECT_GE(y, last) << x;
    EXPECT_LE(y, 1.0f) << x;
    last = y;
  }
  EXPECT_EQ(filmic(1e6f), 1.0f);
}

TEST(Display, AppliedToAFrameKeepsItsSizeAndDropsTheLayers) {
  FrameImage f{2, 1, {0.5f, 1.0f, 2.0f, 4.0f, 0.0f, 0.25f}, {{"hit.r", {1.0f, 2.0f}}}, {}, {}};
  const FrameImage d = DisplayTransform{1.0, ToneCurve::clip}.applied(f);
  EXPECT_EQ(d.width, 2);
  EXPECT_EQ(d.height, 1);
  EXPECT_TRUE(d.layers.empty());
  EXPECT_EQ(d.rgb, (std::vector<float>{1.0f, 2.0f, 4.0f, 8.0f, 0.0f, 0.5f}));
}

}  // namespace
}  // namespace lc
