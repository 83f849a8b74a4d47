// Frame numbers in sentences (store/frame_list.hpp).

#include <gtest/gtest.h>

#include "store/frame_list.hpp"

namespace lc::farm {
namespace {

TEST(FrameList, RunsOfFramesAreCompact) {
  EXPECT_EQ(format_frame_list({4, 0, 1, 2, 7, 9, 10}), "0-2, 4, 7, 9-10");
  EXPECT_EQ(format_frame_list({}), "");
  EXPECT_EQ(format_frame_list({0, 10, 20, 30, 40}, 3), "0, 10, 20, ... (5 frames in all)");
}

TEST(FrameList, ASentenceSaysWasOrWere) {
  EXPECT_EQ(frames_were({3}), "frame 3 was");
  EXPECT_EQ(frames_were({2, 0, 1, 7}), "frames 0-2, 7 were");
}

}  // namespace
}  // namespace lc::farm
