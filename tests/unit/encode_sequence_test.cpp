// Tests of the encode stage's input side: finding a shot's frames in a
// directory, choosing among shots, and telling a stepped sequence (a preview
// rendered every k-th frame) from one with holes, with the holes named
// compactly.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scratch_dir.hpp"
#include "test_errors.hpp"
#include "store/frame_sequence.hpp"

namespace {

namespace fs = std::filesystem;

using lc::test::error_of;
using lc::test::ScratchDir;

TEST(encode_sequence, ContiguousFramesHaveStepOneAndNoHoles) {
  const lc::FrameSpacing s = lc::frame_spacing({3, 4, 5, 6, 7});
  EXPECT_EQ(s.step, 1);
  EXPECT_TRUE(s.missing.empty());
}

TEST(encode_sequence, PreviewStepIsAccepted) {
  // lightcone render --frames 0:899:10 renders 0, 10, ..., 890.
  std::vector<int> frames;
  for (int f = 0; f <= 890; f += 10) frames.push_back(f);
  const lc::FrameSpacing s = lc::frame_spacing(frames);
  EXPECT_EQ(s.step, 10);
  EXPECT_TRUE(s.missing.empty());
}

TEST(encode_sequence, OneOrTwoFramesAreComplete) {
  EXPECT_TRUE(lc::frame_spacing({42}).missing.empty());
  EXPECT_EQ(lc::frame_spacing({42}).step, 1);
  EXPECT_EQ(lc::frame_spacing({5, 35}).step, 30);
  EXPECT_TRUE(lc::frame_spacing({5, 35}).missing.empty());
}

TEST(encode_sequence, HolesAreFoundAtTheSequenceStep) {
  const lc::FrameSpacing s = lc::frame_spacing({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 16, 17, 18, 19, 20, 41});
  EXPECT_EQ(s.step, 1);
  std::vector<int> want = {12, 13, 14, 15};
  for (int f = 21; f <= 40; ++f) want.push_back(f);
  EXPECT_EQ(s.missing, want);
  // Every 10th frame with 30 and 40 lost: the step stays 10.
  const lc::FrameSpacing t = lc::frame_spacing({0, 10, 20, 50, 60});
  EXPECT_EQ(t.step, 10);
  EXPECT_EQ(t.missing, (std::vector<int>{30, 40}));
}

TEST(encode_sequence, AStepMayEndOnOneLastFrameOffTheStep) {
  // --frames 0:95:8 (0, 8, ..., 88), then --frames 95: a preview ending on the last frame.
  std::vector<int> frames;
  for (int f = 0; f <= 88; f += 8) frames.push_back(f);
  frames.push_back(95);
  const lc::FrameSpacing s = lc::frame_spacing(frames);
  EXPECT_EQ(s.step, 8);
  EXPECT_TRUE(s.final_off_step);
  EXPECT_TRUE(s.missing.empty());
  EXPECT_EQ(lc::describe_range(frames, s), "0-88 every 8, then 95");
  // Holes before it are still holes at the step.
  frames.erase(frames.begin() + 2);  // 16
  const lc::FrameSpacing t = lc::frame_spacing(frames);
  EXPECT_EQ(t.step, 8);
  EXPECT_EQ(t.missing, (std::vector<int>{16}));
  // A last gap as long as the step or longer is no such frame: 0, 3, 9 lacks 6.
  const lc::FrameSpacing u = lc::frame_spacing({0, 3, 9});
  EXPECT_FALSE(u.final_off_step);
  EXPECT_EQ(u.missing, (std::vector<int>{6}));
  // Two frames are a progression of their own; contiguous frames have no last frame apart.
  EXPECT_FALSE(lc::frame_spacing({0, 5}).final_off_step);
  EXPECT_FALSE(lc::frame_spacing({0, 1, 2}).final_off_step);
  EXPECT_EQ(lc::describe_range({0, 1, 2}, lc::frame_spacing({0, 1, 2})), "0-2");
  EXPECT_EQ(lc::describe_range({0, 10, 20}, lc::frame_spacing({0, 10, 20})), "0-20 every 10");
}

TEST(encode_sequence, LostFramesOffTheStepAreHolesToo) {
  // The frame numbers 0, 9, 10 look like every 9th plus a last frame; the
  // journal knows 1-8 were rendered and are gone.
  ScratchDir d;
  lc::FrameSequence seq{"s", {0, 9, 10}, {}};
  EXPECT_NO_THROW(lc::require_complete(seq, d.path()));
  const std::string message = error_of([&] { lc::require_complete(seq, d.path(), {1, 2, 3, 4, 5, 6, 7, 8}); });
  EXPECT_NE(message.find("shot s, frames 0-10: missing frames 1-8"), std::string::npos) << message;
}

TEST(encode_sequence, MissingFramesAreListedCompactly) {
  EXPECT_EQ(lc::describe_frames({12, 13, 14, 15, 40}, 1), "12-15, 40");
  EXPECT_EQ(lc::describe_frames({7}, 1), "7");
  EXPECT_EQ(lc::describe_frames({30, 40, 50, 70}, 10), "30-50, 70");
  EXPECT_EQ(lc::describe_frames({1, 3, 5, 7}, 1, 2), "1, 3, ... (4 frames in all)");
}

TEST(encode_sequence, FindsFramesByFinalNameOnly) {
  ScratchDir d;
  for (const char* n : {"kerr.0000.png", "kerr.0001.png", "kerr.0002.png", "kerr.0000.exr", "kerr.0003.png.tmp-77",
                        "kerr.journal", "notes.txt", "kerr.12.png", "my.shot.v2.10000.png"})
    std::ofstream(d / n) << "x";
  fs::create_directories(d / "preview" / "kerr.0004.png");  // a directory, not a frame
  const auto all = lc::find_frame_sequences(d.path());
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all.at("kerr").frames, (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(all.at("kerr").files.back().filename(), "kerr.0002.png");
  EXPECT_EQ(all.at("my.shot.v2").frames, (std::vector<int>{10000}));
}

TEST(encode_sequence, ChoosesTheOnlyShotOrTheNamedOne) {
  ScratchDir d;
  std::ofstream(d / "a.0000.png") << "x";
  std::ofstream(d / "a.0001.png") << "x";
  EXPECT_EQ(lc::select_frame_sequence(d.path(), std::nullopt).shot, "a");
  std::ofstream(d / "b.0005.png") << "x";
  const std::string many = error_of([&] { lc::select_frame_sequence(d.path(), std::nullopt); });
  EXPECT_NE(many.find("a (2 frames), b (1 frames)"), std::string::npos) << many;
  EXPECT_NE(many.find("--shot"), std::string::npos) << many;
  EXPECT_EQ(lc::select_frame_sequence(d.path(), std::string("b")).frames, (std::vector<int>{5}));
  const std::string unknown = error_of([&] { lc::select_frame_sequence(d.path(), std::string("c")); });
  EXPECT_NE(unknown.find("--shot c"), std::string::npos) << unknown;
}

TEST(encode_sequence, EmptyOrMissingDirectoryIsNamed) {
  ScratchDir d;
  const std::string empty = error_of([&] { lc::select_frame_sequence(d.path(), std::nullopt); });
  EXPECT_NE(empty.find(d.path().string() + ": no frames"), std::string::npos) << empty;
  const std::string missing = error_of([&] { lc::select_frame_sequence(d / "nope", std::nullopt); });
  EXPECT_NE(missing.find("no such directory"), std::string::npos) << missing;
}

TEST(encode_sequence, IncompleteSequenceMessageNamesTheHoles) {
  lc::FrameSequence s{"kerr", {0, 10, 20, 50, 60, 80}, {}};
  const std::string m = error_of([&] { lc::require_complete(s, "frames"); });
  EXPECT_NE(m.find("shot kerr, frames 0-80 every 10: missing frames 30-40, 70"), std::string::npos) << m;
  lc::FrameSequence ok{"kerr", {0, 10, 20}, {}};
  EXPECT_NO_THROW(lc::require_complete(ok, "frames"));
}

}  // namespace
