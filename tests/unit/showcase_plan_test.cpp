// The showcase's plan: which frames of which shot at what size and rate.

#include "job/showcase_plan.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "scratch_dir.hpp"

namespace lc {
namespace {

namespace fs = std::filesystem;

const fs::path project_shots = fs::path(LIGHTCONE_SOURCE_DIR) / "shots";

TEST(ShowcasePlan, ProductionIsThePapersSettings) {
  const ShowcasePlan plan = plan_showcase({ShowcaseQuality::production, {}, {}}, project_shots);
  ASSERT_EQ(plan.sequences.size(), 3u);
  EXPECT_EQ(plan.sequences[0].name, "kerr_accrDisk");
  EXPECT_EQ(plan.sequences[1].name, "kerr_passing");
  EXPECT_EQ(plan.sequences[2].name, "dihole");
  const int frames[] = {900, 1700, 2100};
  for (int k = 0; k < 3; ++k) {
    const SequencePlan& s = plan.sequences[k];
    EXPECT_EQ(s.shot_frames, frames[k]);
    ASSERT_EQ(s.frames.size(), static_cast<std::size_t>(frames[k]));
    EXPECT_EQ(s.frames.back(), frames[k] - 1);
    EXPECT_FALSE(s.size);         // the shot's own 1280x720
    EXPECT_FALSE(s.supersample);  // and its 2x2
    EXPECT_FALSE(s.layers);
  }
  EXPECT_EQ(plan.width, 1280);
  EXPECT_EQ(plan.height, 720);
  EXPECT_EQ(plan.fps, 30);
}

TEST(ShowcasePlan, PreviewKeepsTheStorysLengthWithFirstAndLastFrames) {
  const ShowcasePlan plan = plan_showcase({ShowcaseQuality::preview, {}, {}}, project_shots);
  // 30, 56.67 and 70 s of story at 3 frames per second of story.
  const std::size_t counts[] = {90, 170, 210};
  for (int k = 0; k < 3; ++k) {
    const SequencePlan& s = plan.sequences[k];
    ASSERT_EQ(s.frames.size(), counts[k]) << s.name;
    EXPECT_EQ(s.frames.front(), 0);
    EXPECT_EQ(s.frames.back(), s.shot_frames - 1);
    for (std::size_t i = 1; i < s.frames.size(); ++i) EXPECT_LT(s.frames[i - 1], s.frames[i]);
    EXPECT_EQ(s.size, "256x144");
    EXPECT_EQ(s.supersample, 1);
    EXPECT_TRUE(s.layers);
    EXPECT_EQ(s.fps, preview_fps);
  }
}

TEST(ShowcasePlan, ThermalAddsTheFourthSequence) {
  const ShowcasePlan plan = plan_showcase({ShowcaseQuality::preview, {}, {}, true}, project_shots);
  ASSERT_EQ(plan.sequences.size(), 4u);
  EXPECT_EQ(plan.sequences[3].name, "kerr_accrDisk_thermal");
  EXPECT_EQ(plan.sequences[3].shot_frames, 900);  // the first storyboard's
  EXPECT_EQ(plan.sequences[3].frames.size(), 90u);
}

TEST(ShowcasePlan, SizeAndRateOverride) {
  const ShowcasePlan plan = plan_showcase({ShowcaseQuality::preview, "64x36", 0.1}, project_shots);
  EXPECT_EQ(plan.width, 64);
  EXPECT_EQ(plan.fps, 0.1);
  EXPECT_EQ(plan.sequences[0].frames.size(), 4u);  // 30 s x 0.1 = 3, raised to the 4 a clip needs
  EXPECT_EQ(plan.sequences[2].frames.size(), 7u);  // 70 s x 0.1
}

TEST(ShowcasePlan, BadChoicesNameTheFlag) {
  EXPECT_THROW(parse_showcase_quality("draft"), std::invalid_argument);
  try {
    plan_showcase({ShowcaseQuality::production, {}, 2.0}, project_shots);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--rate"), std::string::npos) << e.what();
  }
  EXPECT_THROW(plan_showcase({ShowcaseQuality::preview, {}, 0.0}, project_shots), std::invalid_argument);
  EXPECT_THROW(plan_showcase({ShowcaseQuality::preview, "wide", {}}, project_shots), std::invalid_argument);
  // A size the video cannot have is refused before hours of rendering.
  try {
    plan_showcase({ShowcaseQuality::preview, "16384x16384", {}}, project_shots);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--size 16384x16384: 16384x16384 frames are too large"), std::string::npos)
        << e.what();
  }
}

TEST(ShowcasePlan, ShotsThatCannotBeJoinedAreRefused) {
  test::ScratchDir dir;
  auto shot = [&](const std::string& name, int fps) {
    std::ofstream(dir / (name + ".lua")) << "return {name = '" << name << "', frames = 2, fps = " << fps
                                         << ", width = 32, height = 18, frame = function(i) return {} end}\n";
  };
  shot("kerr_accrDisk", 30);
  shot("kerr_passing", 24);
  shot("dihole", 30);
  try {
    plan_showcase({ShowcaseQuality::production, {}, {}}, dir.path());
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("kerr_passing.lua is 32x18 at 24 fps"), std::string::npos) << e.what();
  }
  fs::remove(dir / "dihole.lua");
  EXPECT_THROW(plan_showcase({ShowcaseQuality::preview, {}, {}}, dir.path()), std::runtime_error);
}

}  // namespace
}  // namespace lc
