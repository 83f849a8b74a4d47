// The sample memo's memory budget: a film-sized frame fits a small machine,
// an absurd one is refused with a message that says what it would take.

#include <gtest/gtest.h>

#include "stages/memo_budget.hpp"
#include "render/sample_memo.hpp"

#include <unistd.h>

namespace lc::farm {
namespace {

TEST(MemoBudget, TheFilmFitsAndAnAbsurdFrameIsRefused) {
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

namespace lc::farm {
namespace {

// A frame's peak, 108 bytes a pixel (docs/performance.md, change 43),
// against what the machine has: a 16384^2 frame needs ~29 GB, refused on a
// 24 GB machine with both figures and what to change; a film frame fits.
TEST(MemoBudget, AFrameLargerThanTheMemoryIsRefusedWithItsFigures) {
  const MemoryBound machine{24ull << 30, "MemAvailable"};
  EXPECT_FALSE(frame_memory_refusal(RenderSettings{1920, 1080, 2, false}, machine).has_value());
  const auto why = frame_memory_refusal(RenderSettings{16384, 16384, 8, false}, machine);
  ASSERT_TRUE(why.has_value());
  for (const char* part : {"16384x16384 need ~29.0 GB", "108 bytes a pixel", "has 25.8 GB (MemAvailable)", "--size",
                           "--region"})
    EXPECT_NE(why->find(part), std::string::npos) << part << " in " << *why;
  // What this process may use is read from the machine: some, and no more
  // than its physical memory.
  const auto here = memory_available();
  ASSERT_TRUE(here.has_value());
  EXPECT_GT(here->bytes, 0u);
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  EXPECT_LE(here->bytes, static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page));
}

}  // namespace
}  // namespace lc::farm
