// Frame ranges as the command line takes them: "A", "A:B", "A:B:STEP",
// inclusive, checked against the shot's frames.

#include "job/frame_range.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace lc {
namespace {

TEST(FrameRange, StepsTakeTheLastFrameOnlyWhenItIsOnTheStep) {
  const FrameRange r = parse_frame_range("0:95:8", 96, "--frames");
  EXPECT_EQ(r.frames().back(), 88);
  EXPECT_EQ(r.last_taken(), 88);
  EXPECT_EQ(r.frames().size(), 12u);
  EXPECT_EQ(parse_frame_range("0:96:8", 97, "--frames").last_taken(), 96);
  EXPECT_EQ(parse_frame_range("5", 10, "--frames").last_taken(), 5);
  EXPECT_EQ(parse_frame_range("2:9", 10, "--frames").frames(), (std::vector<int>{2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(FrameRange, BadRangesAreRefusedNamingTheFlag) {
  EXPECT_THROW(parse_frame_range("5:2", 10, "--frames"), std::invalid_argument);
  EXPECT_THROW(parse_frame_range("0:9:0", 10, "--frames"), std::invalid_argument);
  EXPECT_THROW(parse_frame_range("0:10", 10, "--frames"), std::invalid_argument);
  EXPECT_THROW(parse_frame_range("x", 10, "--frames"), std::invalid_argument);
  EXPECT_THROW(parse_frame_range("99999999999", 10, "--frames"), std::invalid_argument);
  try {
    parse_frame_range("1:2:3:4", 10, "--frames");
    FAIL() << "four parts accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--frames '1:2:3:4'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lc
