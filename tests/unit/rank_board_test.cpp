// What each MPI worker holds (transport/rank_board.hpp): sets handed out and not
// returned, by rank, with their frames.

#include <gtest/gtest.h>

#include "transport/rank_board.hpp"

namespace lc::farm {
namespace {

TEST(RankBoard, HoldsWhatWasHandedAndNotReturned) {
  RankBoard board;
  board.joined(2);
  board.joined(1);
  EXPECT_EQ(board.holdings(), (std::vector<RankHolding>{{1, 0, {}}, {2, 0, {}}}));
  board.handed(1, {{.frame = 4, .stripe = 0}, {.frame = 3, .stripe = 7}, {.frame = 4, .stripe = 1}});
  board.handed(2, {{.frame = 4, .stripe = 2}});
  EXPECT_EQ(board.holdings(), (std::vector<RankHolding>{{1, 3, {3, 4}}, {2, 1, {4}}}));
  board.returned(1, {.frame = 3, .stripe = 7});
  board.returned(1, {.frame = 3, .stripe = 7});  // twice: the queue refuses it, the board ignores it
  board.returned(2, {.frame = 9, .stripe = 0});  // never handed out
  board.returned(5, {.frame = 4, .stripe = 2});  // a rank that never joined
  EXPECT_EQ(board.holdings(), (std::vector<RankHolding>{{1, 2, {4}}, {2, 1, {4}}}));
  // A preview set and a full set of the same stripe are different sets.
  board.handed(2, {{.frame = 4, .stripe = 2, .pass = Pass::preview}});
  board.returned(2, {.frame = 4, .stripe = 2, .pass = Pass::preview});
  EXPECT_EQ(board.holdings()[1], (RankHolding{2, 1, {4}}));
}

}  // namespace
}  // namespace lc::farm
