// The event log's file (store/event_file.hpp): the `held` field of an MPI
// farm round-trips, a malformed entry skipped, and stays within a line.

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "store/event_file.hpp"

namespace lc::farm {
namespace {

TEST(EventFile, TheHeldFieldRoundTrips) {
  // A rank holding nothing is left out: not listed means idle.
  const std::vector<RankHolding> held{{1, 2, {3, 4}}, {2, 0, {}}, {17, 1, {120}}};
  EXPECT_EQ(format_holdings(held), "1:2:3+4,17:1:120");
  EXPECT_EQ(parse_holdings(format_holdings(held)), (std::vector<RankHolding>{{1, 2, {3, 4}}, {17, 1, {120}}}));
  EXPECT_TRUE(parse_holdings("").empty());
  EXPECT_EQ(parse_holdings("2:0:"), (std::vector<RankHolding>{{2, 0, {}}}));
  // Malformed entries are skipped, the good ones kept.
  EXPECT_EQ(parse_holdings("x:1:2,3:1:5,4:2,5:1:6+y,6:a:,7:1:8"), (std::vector<RankHolding>{{3, 1, {5}}, {7, 1, {8}}}));
}

// Thousands of ranks: the field stops whole entries short of its limit
// (an event line longer than the log's limit would be dropped whole) and
// says it did.
TEST(EventFile, TheHeldFieldOfAHugeFarmIsCutShortAndSaysSo) {
  std::vector<RankHolding> held;
  for (int r = 1; r <= 4000; ++r) held.push_back({r, 2, {100000 + r, 100001 + r}});
  bool complete = true;
  const std::string text = format_holdings(held, 8192, &complete);
  EXPECT_FALSE(complete);
  EXPECT_LE(text.size(), 8192u);
  const auto back = parse_holdings(text);
  ASSERT_GT(back.size(), 100u);
  EXPECT_EQ(back.front(), held.front());
  EXPECT_EQ(back.back(), held[back.size() - 1]);  // whole entries only
  format_holdings({held.begin(), held.begin() + 3}, 8192, &complete);
  EXPECT_TRUE(complete);
}

}  // namespace
}  // namespace lc::farm
