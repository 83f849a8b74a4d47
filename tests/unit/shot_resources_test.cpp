// ShotResources (render/scene_builder.hpp): what a shot makes once is
// shared, and what it holds stays within the budget.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "render/scene_builder.hpp"

namespace lc {
namespace {

// A 64 x 32 star field: 64 * 32 * 3 floats.
constexpr std::size_t field_bytes = 64 * 32 * 3 * sizeof(float);

TEST(ShotResources, MakesEachResourceOnce) {
  ShotResources res;
  const auto a = res.starfield(7, 64);
  EXPECT_EQ(res.starfield(7, 64), a);
  EXPECT_NE(res.starfield(8, 64), a);
  EXPECT_EQ(res.bytes(), 2 * field_bytes);
}

TEST(ShotResources, ReleasesWhatNoSceneHoldsToStayWithinItsBudget) {
  // A shot that makes a new star field every frame (or a new worldline)
  // would otherwise keep every one: here ten, room for three.
  ShotResources res({}, 3 * field_bytes);
  const auto kept = res.starfield(100, 64);  // held, as a scene in use holds it
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    ASSERT_NE(res.starfield(seed, 64), nullptr);
    EXPECT_LE(res.bytes(), 3 * field_bytes) << "seed " << seed;
  }
  EXPECT_EQ(res.starfield(100, 64), kept) << "the one in use was released";
}

TEST(ShotResources, RefusesWhatDoesNotFitBesideWhatIsInUse) {
  ShotResources res({}, 3 * field_bytes);
  const auto a = res.starfield(1, 64), b = res.starfield(2, 64), c = res.starfield(3, 64);
  try {
    res.starfield(4, 64);
    FAIL() << "a fourth star field fitted in a budget of three";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a star field (0 MiB) does not fit beside"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("docs/shots.md, Limits"), std::string::npos) << e.what();
  }
  EXPECT_EQ(res.bytes(), 3 * field_bytes);
}

}  // namespace
}  // namespace lc
