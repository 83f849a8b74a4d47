// What each MPI worker holds (farm/rank_board.hpp): sets handed out and not
// returned, by rank, with their frames; and the event log's `held` field
// round-trips, a malformed entry skipped.

#include <gtest/gtest.h>

#include "farm/rank_board.hpp"

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

TEST(RankBoard, TheHeldFieldRoundTrips) {
  const std::vector<RankHolding> held{{1, 2, {3, 4}}, {2, 0, {}}, {17, 1, {120}}};
  EXPECT_EQ(format_holdings(held), "1:2:3+4,2:0:,17:1:120");
  EXPECT_EQ(parse_holdings(format_holdings(held)), held);
  EXPECT_TRUE(parse_holdings("").empty());
  // Malformed entries are skipped, the good ones kept.
  EXPECT_EQ(parse_holdings("x:1:2,3:1:5,4:2,5:1:6+y,6:a:,7:1:8"), (std::vector<RankHolding>{{3, 1, {5}}, {7, 1, {8}}}));
}

}  // namespace
}  // namespace lc::farm
