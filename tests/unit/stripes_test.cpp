// How a frame is cut into working sets (job/stripes.hpp): interleaved rows
// cover the image exactly once.

#include <algorithm>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "job/stripes.hpp"

namespace lc::farm {
namespace {

TEST(Stripes, InterleavedRowsCoverTheImageOnce) {
  for (int height : {1, 7, 32, 720})
    for (int stripes : {1, 3, 32, 512, 1000}) {
      const StripeLayout layout(height, stripes);
      EXPECT_LE(layout.stripes(), height);
      std::vector<int> seen(height, 0);
      for (int s = 0; s < layout.stripes(); ++s) {
        const auto rows = layout.rows(s);
        EXPECT_FALSE(rows.empty());
        EXPECT_EQ(static_cast<int>(rows.size()), layout.row_count(s));
        EXPECT_TRUE(std::is_sorted(rows.begin(), rows.end()));
        for (int j : rows) {
          ++seen[j];
          EXPECT_EQ(layout.stripe_of(j), s);
        }
      }
      EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }))
          << height << " rows, " << stripes << " stripes";
    }
}

TEST(Stripes, PaperLayout) {
  const StripeLayout layout(720, 512);  // 1280x720 in 512 stripes
  EXPECT_EQ(layout.rows(0), (std::vector<int>{0, 512}));
  EXPECT_EQ(layout.rows(207), (std::vector<int>{207, 719}));
  EXPECT_EQ(layout.rows(208), (std::vector<int>{208}));
}

}  // namespace
}  // namespace lc::farm
