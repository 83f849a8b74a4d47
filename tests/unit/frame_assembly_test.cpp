// The frames being made (schedule/frame_assembly.hpp), without the hand-out
// or locks: a frame completes with its last stripe and holds its slot until
// stored, a set not out is refused, and the run's totals count previews.

#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "tiny_frame.hpp"

#include "schedule/frame_assembly.hpp"

namespace lc::farm {
namespace {

TEST(FrameAssembly, AFrameCompletesWithItsLastStripeAndHoldsItsSlotUntilStored) {
  FrameAssembly a(test::settings_of_size(2, 4), StripeLayout(4, 2), 1, {});
  a.open(Pass::full, 7, 2);
  EXPECT_EQ(a.canvas(Pass::full, 7).height, 4);
  a.canvas(Pass::full, 7).rgb[0] = 0.5f;
  EXPECT_FALSE(a.finish({7, 0, Pass::full}, 0, {.rays = 3}, 1, "n1"));
  EXPECT_EQ(a.progress().rows_done, 2);
  const auto done = a.finish({7, 1, Pass::full}, 1, {.rays = 4}, 2, "n2");
  ASSERT_TRUE(done);
  EXPECT_EQ(done->frame, 7);
  EXPECT_EQ(done->image.rgb[0], 0.5f);
  EXPECT_EQ(done->stats.rays, 7);
  EXPECT_EQ(done->makers, (FrameMakers{{{1, "n1"}, {2, "n2"}}, 2}));
  EXPECT_EQ(a.open_count(), 1);
  EXPECT_EQ(a.open_frames(), (std::vector<int>{7}));
  a.stored(Pass::full, 7);
  EXPECT_EQ(a.open_count(), 0);
  EXPECT_EQ(a.progress().frames_stored, 1);
  EXPECT_EQ(a.progress().stats.rays, 7);
}

TEST(FrameAssembly, ASetNotOutIsRefused) {
  FrameAssembly a(test::settings_of_size(2, 4), StripeLayout(4, 2), 2, {});
  EXPECT_THROW(a.finish({0, 0, Pass::full}, 0, {}, 0, ""), std::logic_error);  // frame not open
  a.open(Pass::full, 0, 2);
  EXPECT_THROW(a.finish({0, 5, Pass::full}, -1, {}, 0, ""), std::logic_error);  // no such stripe
  a.finish({0, 0, Pass::full}, 0, {}, 0, "");
  EXPECT_THROW(a.finish({0, 0, Pass::full}, 0, {}, 0, ""), std::logic_error);  // came back twice
  EXPECT_THROW(a.stored(Pass::full, 0), std::logic_error);                     // not complete
  EXPECT_THROW(a.canvas(Pass::full, 1), std::logic_error);                     // not open
}

TEST(FrameAssembly, TheTotalsCountPreviewsAndOnlyFullFramesAreListedOpen) {
  FrameAssembly a(test::settings_of_size(2, 8), StripeLayout(8, 8), 3, {0, 4});
  EXPECT_EQ(a.progress().frames_total, 3);
  EXPECT_EQ(a.progress().previews_total, 3);
  EXPECT_EQ(a.progress().rows_total, 3 * 8 + 3 * 2);
  a.open(Pass::preview, 0, 2);
  a.open(Pass::full, 1, 8);
  EXPECT_EQ(a.open_count(), 2);
  EXPECT_EQ(a.open_frames(), (std::vector<int>{1}));
}

}  // namespace
}  // namespace lc::farm
