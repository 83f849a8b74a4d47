// Image sizes on the command line: "WxH" parsed strictly (a wrapped-around
// number must never render another size), pixels "I,J" alike, and the size
// after --size and --scale.

#include "job/image_size.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "test_errors.hpp"

namespace lc {
namespace {

using test::error_of;

TEST(ImageSize, WidthByHeight) {
  EXPECT_EQ(parse_image_size("1280x720", "--size"), std::make_pair(1280, 720));
  EXPECT_EQ(parse_image_size("33X19", "--size"), std::make_pair(33, 19));
  EXPECT_EQ(parse_image_size("0x10", "--size"), std::make_pair(0, 10));  // the caller's range check names it
}

TEST(ImageSize, NumbersThatDoNotFitAnIntAreRefusedNotWrapped) {
  // 4294967360 = 2^32 + 64: sscanf("%d") made it 64.
  EXPECT_EQ(error_of<std::invalid_argument>([] { parse_image_size("4294967360x36", "--size"); }),
            "--size '4294967360x36': 4294967360 is far too large");
  EXPECT_EQ(error_of<std::invalid_argument>([] { parse_image_size("64x99999999999", "--size"); }),
            "--size '64x99999999999': 99999999999 is far too large");
}

TEST(ImageSize, SignsSpacesAndJunkAreRefusedNamingTheFlag) {
  for (const char* bad : {"-64x36", "64x-36", "+64x36", "64x+36", " 64x36", "64 x36", "64x36 ", "64x36px", "64x",
                          "x36", "64", "", "64x36x2", "64.5x36", "0x40x20", "６４x36", "64,36"}) {
    const std::string message = error_of<std::invalid_argument>([&] { parse_image_size(bad, "--size"); });
    EXPECT_EQ(message, std::string("--size '") + bad + "': expected WxH, two whole numbers of pixels, e.g. 1280x720")
        << bad;
  }
  EXPECT_NE(error_of<std::invalid_argument>([] { parse_image_size("1x", "--title-size"); }).find("--title-size '1x'"), std::string::npos);
}

TEST(ImageSize, PixelsAreParsedAsStrictly) {
  EXPECT_EQ(parse_pixel("12,7", "--pixel"), std::make_pair(12, 7));
  EXPECT_EQ(error_of<std::invalid_argument>([] { parse_pixel("4294967297,0", "--pixel"); }), "--pixel '4294967297,0': 4294967297 is far too large");
  EXPECT_NE(error_of<std::invalid_argument>([] { parse_pixel("-1,0", "--pixel"); }).find("expected I,J"), std::string::npos);
  EXPECT_NE(error_of<std::invalid_argument>([] { parse_pixel("1,2,3", "--pixel"); }).find("expected I,J"), std::string::npos);
}

// --region X0,Y0,X1,Y1: the window's place and size, or an error naming
// the flag and, for a window reaching outside, the frame's size.
TEST(ImageSize, RegionsAreWindowsInsideTheFrame) {
  const Region r = parse_region("3840,5632,4352,6144", 8192, 8192);
  EXPECT_EQ(r.window, (ImageWindow{3840, 5632, 8192, 8192}));
  EXPECT_EQ(r.width, 512);
  EXPECT_EQ(r.height, 512);
  EXPECT_EQ(parse_region("0,0,64,64", 64, 64).width, 64);  // the whole frame is a window too
  EXPECT_EQ(error_of<std::invalid_argument>([] { parse_region("0,0,65,10", 64, 64); }),
            "--region 0,0,65,10: reaches outside the 64x64 frame (X1 at most 64, Y1 at most 64)");
  EXPECT_NE(error_of<std::invalid_argument>([] { parse_region("5,5,5,9", 64, 64); }).find("empty"), std::string::npos);
  for (const char* bad : {"1,2,3", "1,2,3,4,5", "-1,0,4,4", "a,b,c,d", "1, 2,3,4", ""})
    EXPECT_NE(error_of<std::invalid_argument>([&] { parse_region(bad, 64, 64); }).find("expected X0,Y0,X1,Y1"),
              std::string::npos)
        << bad;
}

TEST(ImageSize, OutputSizeAppliesSizeThenScaleAndChecksTheRange) {
  EXPECT_EQ(output_size(1280, 720, std::nullopt, 1.0), std::make_pair(1280, 720));
  EXPECT_EQ(output_size(1280, 720, std::nullopt, 0.25), std::make_pair(320, 180));
  EXPECT_EQ(output_size(1280, 720, std::string("64x36"), 0.5), std::make_pair(32, 18));
  EXPECT_NE(error_of<std::invalid_argument>([] { output_size(8, 8, std::string("0x10"), 1.0); }).find("image size 0x10 is out of range"),
            std::string::npos);
  EXPECT_NE(error_of<std::invalid_argument>([] { output_size(8, 8, std::string("16385x10"), 1.0); }).find("out of range (1 to 16384 a side"),
            std::string::npos);
  // A scale that would overflow an int is a range error, not a wrapped size.
  EXPECT_NE(error_of<std::invalid_argument>([] { output_size(1280, 720, std::nullopt, 1e10); }).find("out of range"), std::string::npos);
  EXPECT_NE(error_of<std::invalid_argument>([] { output_size(8, 8, std::nullopt, -1); }).find("--scale -1: must be a positive number"),
            std::string::npos);
}

}  // namespace
}  // namespace lc
