// Each sample of a pixel at one of the shutter's instants
// (render/sample_times.hpp): every instant as evenly as the pixel's grid
// allows, the same for the same pixel, shuffled between pixels.

#include <gtest/gtest.h>

#include <cstddef>
#include <set>
#include <utility>
#include <vector>

#include "render/sample_times.hpp"

namespace lc {
namespace {

TEST(SampleTimes, APixelSampledInFullTakesEveryInstantAsEvenlyAsItsGridAllows) {
  for (const auto& [N, K] : {std::pair{3, 8}, {4, 16}, {4, 5}, {2, 4}, {5, 1}}) {
    ASSERT_GE(N * N, K);
    const int NN = N * N;
    std::set<std::vector<int>> orders;
    for (int x = 0; x < 40; ++x) {
      const int first = x % 2 == 0 ? 0 : NN - 1;
      std::vector<int> when(static_cast<std::size_t>(NN));
      sample_instants(x, 7, K, first, x % 2 == 1, when);
      std::vector<int> count(static_cast<std::size_t>(K), 0);
      for (int k : when) {
        ASSERT_GE(k, 0);
        ASSERT_LT(k, K);
        ++count[static_cast<std::size_t>(k)];
      }
      for (int c : count) {
        EXPECT_GE(c, NN / K) << N << " " << K;
        EXPECT_LE(c, (NN + K - 1) / K) << N << " " << K;
      }
      // The first sample at the shutter's first or last instant.
      EXPECT_EQ(when[static_cast<std::size_t>(first)], x % 2 == 0 ? 0 : K - 1);
      // The same pixel gives the same times, whoever asks.
      std::vector<int> again(static_cast<std::size_t>(NN));
      sample_instants(x, 7, K, first, x % 2 == 1, again);
      EXPECT_EQ(when, again);
      orders.insert(when);
    }
    // Shuffled per pixel: neighbours do not share one pattern.
    if (K > 1 && NN > 4) {
      EXPECT_GT(orders.size(), 20u) << N << " " << K;
    }
  }
  EXPECT_EQ(samples_per_side(2, 8), 3);
  EXPECT_EQ(samples_per_side(4, 8), 4);
  EXPECT_EQ(samples_per_side(1, 1), 1);
}

}  // namespace
}  // namespace lc
