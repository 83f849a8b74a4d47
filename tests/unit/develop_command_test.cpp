// `lightcone develop`'s looks (pipeline/cli/develop_command.cpp): what a frame's
// look becomes under develop's flags.  A develop must be a fixed point:
// run again, or stopped part way and run again, it gives the same looks,
// so the exposure shift is from the render's own exposure, never from the
// look a develop last applied (issue 43).

#include "cli/develop_command.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace lc {
namespace {

const Look rendered{.exposure = -34.2, .view = View::gamut_safe, .white_balance = 5000, .saturation = 1.2, .bloom = 0.2};

TEST(DevelopCommand, AnExposureShiftIsFromTheRendersExposureSoRunningAgainChangesNothing) {
  const Look once = developed_look(rendered, rendered, {}, 0.5);
  EXPECT_EQ(once.exposure, -33.7);  // as the decimals add, not -33.699999999999996
  const Look twice = developed_look(once, rendered, {}, 0.5);
  EXPECT_EQ(twice, once);
  // A shift of 0 is the render's exposure again; another shift replaces the first.
  EXPECT_EQ(developed_look(once, rendered, {}, 0.0), rendered);
  EXPECT_EQ(developed_look(once, rendered, {}, -1.0).exposure, -35.2);
}

TEST(DevelopCommand, OtherFlagsStartFromTheLookLastAppliedAndKeepItsShift) {
  const Look shifted = developed_look(rendered, rendered, {}, 1.0);
  const Look filmic = developed_look(shifted, rendered, {{"view", "filmic"}}, std::nullopt);
  EXPECT_EQ(filmic.exposure, -33.2);
  EXPECT_EQ(filmic.view, View::filmic);
  EXPECT_EQ(filmic.bloom, 0.2);
  EXPECT_EQ(developed_look(filmic, rendered, {{"view", "filmic"}}, std::nullopt), filmic);
  // --exposure sets the exposure outright; a shift then adds to it.
  EXPECT_EQ(developed_look(shifted, rendered, {{"exposure", "-30"}}, std::nullopt).exposure, -30.0);
  EXPECT_EQ(developed_look(shifted, rendered, {{"exposure", "-30"}}, 0.25).exposure, -29.75);
}

TEST(DevelopCommand, AShiftOutOfRangeNamesTheFlag) {
  try {
    developed_look(rendered, rendered, {}, -40.0);
    FAIL() << "accepted an exposure of -74 stops";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "--exposure-shift -40: takes an exposure to -74.2 stops, outside -64 to 64");
  }
}

}  // namespace
}  // namespace lc
