// The sample memo's memory budget: a film-sized frame fits a small machine,
// an absurd one is refused with a message that says what it would take.

#include <gtest/gtest.h>

#include "farm/memo_budget.hpp"
#include "render/sample_memo.hpp"

namespace lc::farm {
namespace {

TEST(FarmMemoBudget, TheFilmFitsAndAnAbsurdFrameIsRefused) {
  const RenderSettings film{1280, 720, 2, false};
  // 44 bytes a sample: colour, the six layers (the first is the hit kind)
  // and the frame times it holds for; and 32 a pixel for its sky point
  // (point stars).
  EXPECT_EQ(SampleMemo::bytes_for(film), 1280u * 720u * (5u * 44u + 32u));  // ~232 MB
  EXPECT_FALSE(memo_refusal(film, 1).has_value());
  const RenderSettings huge{16384, 16384, 16, false};  // ~2.2 TB of samples
  const auto why = memo_refusal(huge, 1);
  ASSERT_TRUE(why.has_value());
  EXPECT_NE(why->find("16384x16384 with 16x16 samples"), std::string::npos) << *why;
  EXPECT_NE(why->find("--no-reuse"), std::string::npos) << *why;
}

}  // namespace
}  // namespace lc::farm
