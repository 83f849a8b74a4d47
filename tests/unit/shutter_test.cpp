// A frame's shutter (scene/shutter.hpp): the instants it is cut into, and
// which setting wins (docs/motion_blur.md).

#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "scene/shutter.hpp"

namespace lc {
namespace {

TEST(Shutter, InstantsAreTheCentresOfEqualPartsOfTheOpenInterval) {
  const Shutter centre{0.5, ShutterPosition::centre, 4};
  EXPECT_EQ(centre.instants(), (std::vector<double>{-0.1875, -0.0625, 0.0625, 0.1875}));
  const Shutter start{0.5, ShutterPosition::start, 2};
  EXPECT_EQ(start.instants(), (std::vector<double>{0.125, 0.375}));
  const Shutter end{1.0, ShutterPosition::end, 2};
  EXPECT_EQ(end.instants(), (std::vector<double>{-0.75, -0.25}));
  EXPECT_TRUE(Shutter{}.instants().empty());  // closed by default
  // The command line over the frame's over the shot's.
  const Shutter shot{0.5, ShutterPosition::centre, 8};
  EXPECT_EQ(frame_shutter(shot, 0.25, {}).open, 0.25);
  EXPECT_EQ(frame_shutter(shot, 0.25, {.open = 0.0}).open, 0.0);
  EXPECT_EQ(frame_shutter(shot, std::nullopt, {.time_samples = 3}).time_samples, 3);
}

}  // namespace
}  // namespace lc
