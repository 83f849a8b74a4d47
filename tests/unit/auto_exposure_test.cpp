// Automatic exposure's arithmetic (image/auto_exposure.hpp): the meter's
// percentile by the nearest-rank rule, exposures that bring each reading to
// the level, smoothing that follows a steady climb, evens out a flicker and
// ignores frames with nothing lit.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>

#include "image/auto_exposure.hpp"

namespace lc {
namespace {

// A one-row image whose pixels are grey at the given luminances.
FrameImage greys(const std::vector<float>& luminance) {
  FrameImage image{static_cast<int>(luminance.size()), 1, {}, {}, {}, {}};
  for (float y : luminance) image.rgb.insert(image.rgb.end(), {y, y, y});
  return image;
}

TEST(AutoExposure, TheReadingIsTheNearestRankPercentileOfLuminance) {
  std::vector<float> y;
  for (int i = 1; i <= 200; ++i) y.push_back(static_cast<float>(i));
  // 99% of 200 pixels: the 198th smallest.
  EXPECT_DOUBLE_EQ(luminance_percentile(greys(y)), 198.0);
  EXPECT_DOUBLE_EQ(luminance_percentile(greys(y), 0.5), 100.0);
  EXPECT_DOUBLE_EQ(luminance_percentile(greys({5.0f})), 5.0);
  // Colour counts by its Rec. 709 luminance; NaN and negative light as 0.
  FrameImage green{1, 1, {0.0f, 1.0f, 0.0f}, {}, {}, {}};
  EXPECT_NEAR(luminance_percentile(green), 0.7152, 1e-7);
  EXPECT_EQ(luminance_percentile(greys({std::numeric_limits<float>::quiet_NaN(), -1.0f}), 1.0), 0.0);
}

TEST(AutoExposure, WithoutSmoothingEachReadingIsShownAtTheLevel) {
  const std::vector<double> readings = {1.0, 4.0, 0.25, 1e10};
  const std::vector<double> e = metered_exposures(readings, 1.0, 0.0);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[0], 0.0);
  EXPECT_EQ(e[1], -2.0);
  EXPECT_EQ(e[2], 2.0);
  EXPECT_NEAR(e[3], -std::log2(1e10), 1e-12);
  EXPECT_EQ(metered_exposures(readings, 2.0, 0.0)[1], -1.0);
}

// A climb steady in stops is followed exactly, to the shot's ends (the
// local fit of a straight line is the line, where a weighted mean would
// lag a one-sided window by a third of a stop here).
TEST(AutoExposure, SmoothingFollowsASteadyClimbAndEvensAFlicker) {
  std::vector<double> climb;
  for (int i = 0; i < 120; ++i) climb.push_back(std::exp2(3.0 * i / 119.0));  // 3 stops over the shot
  const std::vector<double> e = metered_exposures(climb, 1.0, 6.0);
  for (int i = 0; i < 120; ++i) EXPECT_NEAR(e[i], -3.0 * i / 119.0, 1e-9) << i;
  // Light that flickers by a stop frame to frame is shown steady.
  std::vector<double> flicker;
  for (int i = 0; i < 60; ++i) flicker.push_back(i % 2 ? 2.0 : 1.0);
  const std::vector<double> f = metered_exposures(flicker, 1.0, 4.0);
  for (int i = 12; i < 48; ++i) EXPECT_NEAR(f[i], -0.5, 0.01) << i;
}

TEST(AutoExposure, FramesWithNothingLitTakeTheirNeighboursExposure) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> readings = {0.0, 0.0, 4.0, 4.0, 0.0, nan, 0.0, 0.0, 0.0, 16.0};
  const std::vector<double> none = metered_exposures(readings, 1.0, 0.0);
  EXPECT_EQ(none, (std::vector<double>{-2, -2, -2, -2, -2, -2, -2, -4, -4, -4}));
  // With smoothing, a dark frame within reach of lit ones is placed by them.
  const std::vector<double> smooth = metered_exposures(readings, 1.0, 1.0);
  for (double x : smooth) EXPECT_TRUE(x <= -2.0 && x >= -4.0) << x;
  // Nothing lit anywhere: no change to the shot's exposure.
  EXPECT_EQ(metered_exposures(std::vector<double>{0.0, 0.0}, 1.0, 3.0), (std::vector<double>{0.0, 0.0}));
  // The shot's range bounds it.
  EXPECT_EQ(metered_exposures(std::vector<double>{1e-30}, 1.0, 0.0)[0], 64.0);
}

// Metering only the frames the exposures of a few need (issue 43, item 17)
// gives each exactly what metering the whole shot gives it: over shots with
// light that climbs and flickers, dark stretches longer than the
// smoothing's reach (where a frame takes a placed neighbour's fit, however
// far), NaN, a shot dark throughout, every smoothing from none to wider
// than the shot, and single frames, runs, steps and scattered sets.  Each
// frame is taken once, and a lit shot's few frames take a few dozen.
TEST(AutoExposure, TheNeededReadingsGiveTheWholeShotsExposuresToTheBit) {
  const int count = 300;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::vector<double>> shots;
  std::vector<double> lit(count), dark_gaps(count), dark(count, 0.0), scarce(count, 0.0);
  for (int i = 0; i < count; ++i) {
    lit[i] = std::exp(0.01 * i) * (1.0 + 0.2 * std::sin(1.7 * i));
    dark_gaps[i] = (i % 100 < 55) ? 0.0 : (i % 7 == 0 ? nan : lit[i]);
  }
  scarce[40] = 2.0, scarce[250] = 0.5;
  shots = {lit, dark_gaps, dark, scarce};
  const std::vector<std::vector<int>> asks = {
      {0}, {120}, {299}, {10, 11, 12}, {0, 60, 120, 180, 240}, {3, 77, 150, 151, 298}, {45, 260}, {0, 299}};
  for (std::size_t s = 0; s < shots.size(); ++s)
    for (const double smoothing : {0.0, 1.0, 2.5, 12.0, 150.0}) {
      const std::vector<double> whole = metered_exposures(shots[s], 1.0, smoothing);
      for (const auto& frames : asks) {
        std::map<int, int> taken;
        const auto readings = needed_readings(frames, count, smoothing, [&](const std::vector<int>& batch) {
          std::vector<double> out;
          for (int f : batch) {
            ++taken[f];
            out.push_back(shots[s][static_cast<std::size_t>(f)]);
          }
          return out;
        });
        for (const auto& [f, n] : taken) EXPECT_EQ(n, 1) << "frame " << f << " taken twice";
        const auto got = exposures_from(readings, frames, 1.0, smoothing);
        for (int f : frames) {
          const double want = whole[static_cast<std::size_t>(f)];
          EXPECT_EQ(std::memcmp(&got.at(f), &want, sizeof want), 0)
              << "shot " << s << ", smoothing " << smoothing << ", frame " << f << ": " << got.at(f) << " vs " << want;
        }
        if (s == 0 && smoothing == 12.0 && frames.size() == 1) EXPECT_LE(readings.size(), 73u);
      }
    }
}

}  // namespace
}  // namespace lc
