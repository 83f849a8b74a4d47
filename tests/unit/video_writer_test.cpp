// Tests of VideoWriter and the encode options through the real FFmpeg
// libraries, at tiny sizes: the file shows under its final name only after
// finish(), an abandoned writer leaves nothing, a frame of the wrong size
// and bad options are refused with the flag or file named.  (The encoded
// stream itself is checked with ffprobe in tests/e2e/encode.sh.)

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "scratch_dir.hpp"
#include "tiny_frame.hpp"
#include "test_errors.hpp"
#include "image/image_io.hpp"
#include "video/concat_videos.hpp"
#include "video/contact_sheet.hpp"
#include "video/encode_options.hpp"
#include "video/encode_sequence.hpp"
#include "video/video_writer.hpp"

namespace {

namespace fs = std::filesystem;

using lc::test::error_of;
using lc::test::ScratchDir;
using Names = std::vector<std::string>;

TEST(VideoWriter, FileAppearsOnlyAfterFinish) {
  ScratchDir d;
  const fs::path out = d / "clip.mp4";
  lc::VideoWriter w(out, 16, 8, lc::EncodeOptions{});
  for (int i = 0; i < 3; ++i) w.add(lc::Rgb8Image::filled(16, 8, static_cast<std::uint8_t>(80 * i), 40, 200));
  EXPECT_FALSE(fs::exists(out));
  w.finish();
  EXPECT_TRUE(fs::exists(out));
  EXPECT_GT(fs::file_size(out), 100u);
  EXPECT_EQ(d.names(), Names{"clip.mp4"}) << "a temporary was left behind";
  EXPECT_EQ(w.frames(), 3);
}

TEST(VideoWriter, AbandonedWriterLeavesNothing) {
  ScratchDir d;
  {
    lc::VideoWriter w(d / "clip.mp4", 16, 8, lc::EncodeOptions{});
    w.add(lc::Rgb8Image::filled(16, 8, 1, 2, 3));
  }
  EXPECT_TRUE(d.names().empty());
}

TEST(VideoWriter, OddSizeIsPaddedToEven) {
  ScratchDir d;
  lc::VideoWriter w(d / "odd.mp4", 15, 9, lc::EncodeOptions{});
  EXPECT_EQ(w.encoded_width(), 16);
  EXPECT_EQ(w.encoded_height(), 10);
  w.add(lc::Rgb8Image::filled(15, 9, 9, 9, 9));
  w.finish();
}

TEST(VideoWriter, WrongFrameSizeAndNoFramesAreRefused) {
  ScratchDir d;
  lc::VideoWriter w(d / "clip.mp4", 16, 8, lc::EncodeOptions{});
  const std::string m = error_of<std::invalid_argument>([&] { w.add(lc::Rgb8Image::filled(8, 8, 0, 0, 0)); });
  EXPECT_NE(m.find("8x8, the video is 16x8"), std::string::npos) << m;
  const std::string none = error_of<std::runtime_error>([&] { w.finish(); });
  EXPECT_NE(none.find("no frames"), std::string::npos) << none;
}

TEST(VideoWriter, UnwritableOutputIsNamed) {
  ScratchDir d;
  const fs::path out = d / "missing" / "clip.mp4";
  const std::string m = error_of<std::runtime_error>([&] { lc::VideoWriter(out, 16, 8, lc::EncodeOptions{}); });
  EXPECT_NE(m.find("cannot write " + out.string()), std::string::npos) << m;
  fs::create_directories(d / "taken.mp4");
  const std::string dir =
      error_of<std::runtime_error>([&] { lc::VideoWriter(d / "taken.mp4", 16, 8, lc::EncodeOptions{}); });
  EXPECT_NE(dir.find("is a directory"), std::string::npos) << dir;
}

TEST(VideoWriter, OptionsAreCheckedAgainstTheCodec) {
  using lc::Codec;
  EXPECT_EQ(lc::parse_codec("hevc"), Codec::hevc);
  EXPECT_NE(error_of<std::invalid_argument>([] { lc::parse_codec("h265"); }).find("--codec h265"), std::string::npos);
  lc::EncodeOptions o;
  o.crf = 52;
  EXPECT_NE(error_of<std::invalid_argument>([&] { lc::validate(o); }).find("--crf 52"), std::string::npos);
  o.codec = Codec::vp9;
  EXPECT_NO_THROW(lc::validate(o));
  o.crf.reset();
  o.preset = "medium";
  EXPECT_NE(error_of<std::invalid_argument>([&] { lc::validate(o); }).find("--preset medium"), std::string::npos);
  o = {};
  o.fps = {0, 1};
  EXPECT_NE(error_of<std::invalid_argument>([&] { lc::validate(o); }).find("--fps"), std::string::npos);
  o = {};
  o.codec = Codec::prores;
  o.crf = 10;
  EXPECT_NE(error_of<std::invalid_argument>([&] { lc::validate(o); }).find("ProRes has no CRF"), std::string::npos);
  EXPECT_EQ(lc::container_for("a/b.MP4", Codec::h264), lc::Container::mp4);
  EXPECT_NE(error_of<std::invalid_argument>([] { lc::container_for("x.mp4", lc::Codec::prores); }).find(".mov"),
            std::string::npos);
  EXPECT_NE(error_of<std::invalid_argument>([] { lc::container_for("x.avi", lc::Codec::h264); }).find("'.avi'"),
            std::string::npos);
}

TEST(VideoWriter, FrameRatesAreExactFractions) {
  using lc::FrameRate;
  EXPECT_EQ(lc::parse_frame_rate("30", "--fps"), (FrameRate{30, 1}));
  EXPECT_EQ(lc::parse_frame_rate("30000/1001", "--fps"), (FrameRate{30000, 1001}));
  EXPECT_EQ(lc::parse_frame_rate("48/2", "--fps"), (FrameRate{24, 1}));  // in lowest terms
  EXPECT_EQ(lc::parse_frame_rate("29.97", "--fps"), (FrameRate{2997, 100}));
  EXPECT_EQ(lc::parse_frame_rate("2.5e1", "--fps"), (FrameRate{25, 1}));
  EXPECT_EQ(lc::parse_frame_rate(".5", "--fps"), (FrameRate{1, 2}));
  // A long decimal becomes the nearest fraction with small terms (what the
  // renderer records for a third: "0.3333333333333333").
  EXPECT_EQ(lc::parse_frame_rate("0.3333333333333333", "--fps"), (FrameRate{1, 3}));
  EXPECT_EQ(lc::parse_frame_rate("29.97002997002997", "--fps"), (FrameRate{30000, 1001}));
  // The ends of the range are allowed, beyond them not.
  EXPECT_EQ(lc::parse_frame_rate("1/1000", "--fps"), (FrameRate{1, 1000}));
  EXPECT_EQ(lc::parse_frame_rate("1000", "--fps"), (FrameRate{1000, 1}));
  const std::string range = "must be from 1/1000 (one frame every 1000 s) to 1000 frames per second";
  for (const char* bad : {"1e-9", "0", "0.0009", "1001", "1000001/1000", "1/1001", "1e400", "0/5", "1234567890/1"})
    EXPECT_EQ(error_of<std::invalid_argument>([&] { lc::parse_frame_rate(bad, "--fps"); }),
              std::string("--fps ") + bad + ": " + range)
        << bad;
  for (const char* junk : {"", "abc", "-30", "+30", "inf", "nan", "30fps", "30 ", "30/", "/2", "30/-1", "1.5/2",
                           "30/1001/2", "0x1e"})
    EXPECT_NE(error_of<std::invalid_argument>([&] { lc::parse_frame_rate(junk, "--fps"); })
                  .find(std::string("--fps '") + junk + "': expected frames per second"),
              std::string::npos)
        << junk;
  EXPECT_EQ(error_of<std::invalid_argument>([] { lc::parse_frame_rate("30/0", "--fps"); }), "--fps 30/0: the denominator is 0");
  // A fraction is one however long its numbers (issue #25: "expected a
  // number or a fraction"); in range but with terms too large, it says so.
  EXPECT_EQ(lc::parse_frame_rate("60000000000/2000000000", "--fps"), (FrameRate{30, 1}));
  const std::string large = ": too large: in lowest terms the fraction's numbers must be at most 1001000 (as in 30000/1001)";
  for (const char* big : {"4294967297/4294967296", "30000001/1000000", "1000000000000000000000/1000000000000000000000"})
    EXPECT_EQ(error_of<std::invalid_argument>([&] { lc::parse_frame_rate(big, "--fps"); }), std::string("--fps ") + big + large)
        << big;
  EXPECT_EQ(lc::describe(FrameRate{24, 1}), "24");
  EXPECT_EQ(lc::describe(FrameRate{2997, 100}), "29.97");
  EXPECT_EQ(lc::describe(FrameRate{30000, 1001}), "30000/1001 (29.97)");
  EXPECT_EQ(lc::frame_rate_divided(FrameRate{24, 1}, 8), (FrameRate{3, 1}));
  EXPECT_EQ(lc::frame_rate_divided(FrameRate{30000, 1001}, 10), (FrameRate{3000, 1001}));
  EXPECT_EQ(lc::frame_rate_near(3.0), (FrameRate{3, 1}));
  EXPECT_EQ(lc::frame_rate_near(-1.0), (FrameRate{0, 1}));
}

TEST(VideoWriter, SizesTheEncodersCannotTakeAreRefusedBeforeOpening) {
  using lc::Codec;
  // FFmpeg's av_image_check_size: (W+128)(H+128) < INT_MAX/8.
  EXPECT_FALSE(lc::size_refusal(Codec::h264, 16384, 16128));
  EXPECT_FALSE(lc::size_refusal(Codec::h264, 16254, 16254));
  EXPECT_FALSE(lc::size_refusal(Codec::h264, 16253, 16253));  // padded to 16254 x 16254
  EXPECT_TRUE(lc::size_refusal(Codec::h264, 16384, 16130));
  EXPECT_TRUE(lc::size_refusal(Codec::h264, 16256, 16256));
  const auto big = lc::size_refusal(Codec::h264, 16384, 16384);
  ASSERT_TRUE(big);
  EXPECT_NE(big->find("16384x16384 frames are too large for FFmpeg's encoders"), std::string::npos) << *big;
  EXPECT_TRUE(lc::size_refusal(Codec::vp9, 16384, 16384));
  // libx264 takes at most 16384 a side; SVT-AV1 64x64 to 16384x8704.
  EXPECT_NE(lc::size_refusal(Codec::h264, 16400, 100).value_or("").find("libx264 takes at most 16384"), std::string::npos);
  EXPECT_FALSE(lc::size_refusal(Codec::vp9, 16400, 100));
  EXPECT_TRUE(lc::size_refusal(Codec::av1, 62, 64));
  EXPECT_FALSE(lc::size_refusal(Codec::av1, 63, 64));  // padded to 64 x 64
  EXPECT_FALSE(lc::size_refusal(Codec::av1, 64, 64));
  EXPECT_FALSE(lc::size_refusal(Codec::av1, 16384, 8704));
  EXPECT_NE(lc::size_refusal(Codec::av1, 1920, 8706).value_or("").find("64x64 to 16384x8704"), std::string::npos);
  EXPECT_FALSE(lc::size_refusal(Codec::h264, 1, 1));
  // Beyond H.264 level 6.2 (139264 macroblocks) it encodes, with a warning.
  EXPECT_FALSE(lc::size_warning(Codec::h264, 8192, 4320));  // 512 x 270 = 138240 macroblocks
  EXPECT_FALSE(lc::size_warning(Codec::h264, 4096, 2160));
  EXPECT_NE(lc::size_warning(Codec::h264, 8192, 8192).value_or("").find("beyond H.264's largest level"),
            std::string::npos);
  EXPECT_FALSE(lc::size_warning(Codec::vp9, 8192, 8192));
  // The writer refuses at once, naming the file and the limit, and leaves
  // nothing (it used to fail inside the encoder with "(0x0): Invalid argument").
  ScratchDir d;
  const std::string message =
      error_of<std::invalid_argument>([&] { lc::VideoWriter(d / "big.mp4", 16384, 16384, lc::EncodeOptions{}); });
  EXPECT_NE(message.find("big.mp4: 16384x16384 frames are too large"), std::string::npos) << message;
  EXPECT_TRUE(d.names().empty());
}

TEST(VideoWriter, StillHoldsForTheFramesAsked) {
  ScratchDir d;
  int calls = 0, last_total = 0;
  const lc::EncodeResult r =
      lc::encode_still(lc::Rgb8Image::filled(16, 8, 200, 0, 0), 5, lc::EncodeOptions{}, d / "still.mp4",
                       [&](int done, int total) {
                         ++calls;
                         last_total = total;
                         EXPECT_EQ(done, calls);
                       });
  EXPECT_EQ(r.frames, 5);
  EXPECT_DOUBLE_EQ(r.seconds, 5.0 / 30.0);
  EXPECT_EQ(calls, 5);
  EXPECT_EQ(last_total, 5);
}

// The showcase's videos and sheets are its folder's own files (issue 43):
// a link planted under one of their names is replaced, never written
// through; a user's -o still writes through a link, as a shell's `>`.
TEST(VideoWriter, AnOwnNameIsReplacedNotWrittenThroughALink) {
  ScratchDir d;
  std::ofstream(d / "outside.txt") << "not lightcone's";
  const auto outside_unchanged = [&] {
    std::ifstream in(d / "outside.txt");
    return std::string(std::istreambuf_iterator<char>(in), {}) == "not lightcone's";
  };
  fs::create_symlink(d / "outside.txt", d / "clip.mp4");
  lc::EncodeOptions own;
  own.output_name = lc::FinalName::own;
  lc::encode_still(lc::Rgb8Image::filled(16, 8, 200, 0, 0), 4, own, d / "clip.mp4");
  EXPECT_TRUE(outside_unchanged());
  EXPECT_FALSE(fs::is_symlink(d / "clip.mp4"));
  EXPECT_GT(fs::file_size(d / "clip.mp4"), 100u);
  fs::create_symlink(d / "outside.txt", d / "film.mp4");
  lc::concat_videos({d / "clip.mp4", d / "clip.mp4"}, d / "film.mp4", {}, {}, lc::FinalName::own);
  EXPECT_TRUE(outside_unchanged());
  EXPECT_FALSE(fs::is_symlink(d / "film.mp4"));
  lc::FrameSequence seq;
  seq.shot = "s";
  for (int f = 0; f < 2; ++f) {
    seq.frames.push_back(f);
    seq.files.push_back(d / ("s.000" + std::to_string(f) + ".png"));
    lc::write_png(seq.files.back(), lc::test::tiny_frame());
  }
  fs::create_symlink(d / "outside.txt", d / "s.sheet.png");
  lc::write_contact_sheet(seq, {2, 64, 16, lc::FinalName::own}, d / "s.sheet.png");
  EXPECT_TRUE(outside_unchanged());
  EXPECT_FALSE(fs::is_symlink(d / "s.sheet.png"));
}

TEST(VideoWriter, ProgressMayAbandonTheEncoding) {
  // How a Ctrl-C reaches the encoder: the progress callback throws.
  ScratchDir d;
  struct Stop {};
  EXPECT_THROW(lc::encode_still(lc::Rgb8Image::filled(16, 8, 0, 0, 0), 10, lc::EncodeOptions{}, d / "x.mp4",
                                [](int done, int) {
                                  if (done == 3) throw Stop{};
                                }),
               Stop);
  EXPECT_TRUE(d.names().empty());
}

}  // namespace
