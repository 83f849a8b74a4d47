// The hand-out order (schedule/hand_out.hpp), without canvases or locks:
// sets come out frame by frame and each once, a frame opens only when
// allowed, previews come first, and a taker gets back the stripes it had.

#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "schedule/hand_out.hpp"

namespace lc::farm {
namespace {

// Every set `h` hands out to `taker`, always allowed to open a frame.
std::vector<HandOut::Next> all_of(HandOut& h, int taker = -1) {
  std::vector<HandOut::Next> out;
  while (auto n = h.next(taker, true)) out.push_back(*n);
  return out;
}

TEST(HandOut, EverySetOnceFrameByFrame) {
  HandOut h(StripeLayout(6, 3), {5, 2}, 0);
  const auto sets = all_of(h);
  ASSERT_EQ(sets.size(), 6u);
  for (std::size_t i = 0; i < sets.size(); ++i) {
    EXPECT_EQ(sets[i].item, (WorkItem{i < 3 ? 5 : 2, static_cast<int>(i % 3), Pass::full}));
    EXPECT_EQ(sets[i].opens, i % 3 == 0);  // a frame's first set opens it
  }
  EXPECT_TRUE(h.drained());
  EXPECT_FALSE(h.next(-1, true));
}

TEST(HandOut, AFrameOpensOnlyWhenAllowedAndAnOpenOneGoesOn) {
  HandOut h(StripeLayout(4, 2), {0, 1}, 0);
  EXPECT_FALSE(h.next(-1, false));
  const auto first = h.next(-1, true);
  ASSERT_TRUE(first);
  EXPECT_TRUE(first->opens);
  const auto second = h.next(-1, false);  // frame 0 is open: its sets go on
  ASSERT_TRUE(second);
  EXPECT_EQ(second->item, (WorkItem{0, 1, Pass::full}));
  EXPECT_FALSE(h.next(-1, false));  // frame 1 would open
  EXPECT_FALSE(h.drained());
}

TEST(HandOut, PreviewStripesOfEveryFrameComeFirst) {
  HandOut h(StripeLayout(8, 8), {0, 1}, 4);
  EXPECT_EQ(h.stripes_of(Pass::preview), (std::vector<int>{0, 4}));
  const auto sets = all_of(h);
  ASSERT_EQ(sets.size(), 2u * 2 + 2u * 8);
  EXPECT_EQ(sets[0].item, (WorkItem{0, 0, Pass::preview}));
  EXPECT_EQ(sets[1].item, (WorkItem{0, 4, Pass::preview}));
  EXPECT_EQ(sets[3].item, (WorkItem{1, 4, Pass::preview}));
  EXPECT_EQ(sets[4].item, (WorkItem{0, 0, Pass::full}));
  EXPECT_EQ(h.index_of({0, 4, Pass::preview}), 1);
  EXPECT_EQ(h.index_of({0, 3, Pass::preview}), -1);  // not a preview stripe
  EXPECT_EQ(h.index_of({0, 8, Pass::full}), -1);     // no such stripe
}

// A still scene's rows go back to the worker that kept their samples.
TEST(HandOut, ATakerGetsBackTheStripesItHadBefore) {
  HandOut h(StripeLayout(4, 4), {0, 1}, 0);
  EXPECT_EQ(h.next(1, true)->item.stripe, 0);
  EXPECT_EQ(h.next(1, true)->item.stripe, 1);
  EXPECT_EQ(h.next(2, true)->item.stripe, 2);
  EXPECT_EQ(h.next(2, true)->item.stripe, 3);
  const auto a = h.next(2, true);
  EXPECT_EQ(a->item, (WorkItem{1, 2, Pass::full}));
  EXPECT_TRUE(a->opens);
  EXPECT_EQ(h.next(1, true)->item.stripe, 0);
  EXPECT_EQ(h.next(-1, true)->item.stripe, 1);  // in order: the lowest left
  EXPECT_EQ(h.next(1, true)->item.stripe, 3);
  EXPECT_TRUE(h.drained());
}

}  // namespace
}  // namespace lc::farm
