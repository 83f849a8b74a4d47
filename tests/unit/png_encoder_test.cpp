// The 8-bit PNG encoder (image/png_encoder.hpp) makes the very bytes
// OpenImageIO's PNG writer (libpng) makes for the same pixels: for every
// shape libpng treats apart (one pixel, one row, one column, images small
// enough for a smaller zlib window and just too large for it, several
// IDAT chunks) and content that exercises each filter (smooth ramps, flat
// colour where filters tie, noise, hard edges).  The frames' PNGs so stay
// what they were when OpenImageIO wrote them.  That holds for the libpng
// the bytes were fixed to; on any, a PNG made reads back as its pixels.

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "image/png_encoder.hpp"
#include "scratch_dir.hpp"

namespace lc {
namespace {

namespace fs = std::filesystem;

std::vector<unsigned char> oiio_png(const fs::path& path, const std::vector<std::uint8_t>& rgb, int w, int h) {
  OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
  spec.attribute("oiio:ColorSpace", "sRGB");
  auto out = OIIO::ImageOutput::create("png");
  EXPECT_TRUE(out && out->open(path.string(), spec)) << OIIO::geterror();
  EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, rgb.data()));
  EXPECT_TRUE(out->close());
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

enum class Content { ramp, flat, noise, edges, mixed };

std::vector<std::uint8_t> pixels(int w, int h, Content content, unsigned seed) {
  std::vector<std::uint8_t> rgb(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  std::mt19937 random(seed);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) +
                              static_cast<std::size_t>(c);
        switch (content) {
          case Content::ramp: rgb[i] = static_cast<std::uint8_t>(x * 3 + y * 2 + c * 40); break;
          case Content::flat: rgb[i] = static_cast<std::uint8_t>(c == 0 ? 200 : 17); break;
          case Content::noise: rgb[i] = static_cast<std::uint8_t>(random()); break;
          case Content::edges: rgb[i] = ((x / 3 + y / 2) % 2) != 0 ? 255 : static_cast<std::uint8_t>(c * 9); break;
          case Content::mixed: {
            // A glow on black with speckles: what a frame of the disk looks like.
            const double r = std::hypot(x - w / 2.0, y - h / 2.0) / (w + 1.0);
            rgb[i] = random() % 50 == 0 ? static_cast<std::uint8_t>(random())
                                        : static_cast<std::uint8_t>(std::max(0.0, 255.0 * (1.0 - 3.0 * r)) * (c + 1) / 3);
          }
        }
      }
  return rgb;
}

// The shapes and contents both tests below go through.
struct Case {
  int w, h;
  Content content;
  unsigned seed;
};
std::vector<Case> cases() {
  // 5x1024 and 48x113: 16,384 and 16,385 bytes filtered, either side of
  // libpng's smaller window.
  const std::vector<std::pair<int, int>> shapes = {{1, 1},   {1, 9},   {9, 1},    {2, 2},    {5, 3},
                                                   {33, 17}, {64, 64}, {73, 74},  {75, 75},  {5, 1024},
                                                   {48, 113}, {1, 4097}, {5461, 1}, {200, 150}, {640, 360}};
  std::vector<Case> out;
  unsigned seed = 1;
  for (const auto& [w, h] : shapes)
    for (const Content content : {Content::ramp, Content::flat, Content::noise, Content::edges, Content::mixed})
      out.push_back({w, h, content, seed++});
  return out;
}

// Whatever library versions are installed: each PNG made reads back, through
// OpenImageIO's reader (libpng), as its pixels, 8-bit RGB, marked sRGB.
TEST(PngEncoder, ReadsBackAsItsPixels) {
  test::ScratchDir dir;
  for (const Case& c : cases()) {
    const std::vector<std::uint8_t> rgb = pixels(c.w, c.h, c.content, c.seed);
    const std::vector<unsigned char> made = encode_png8(rgb, c.w, c.h);
    const fs::path file = dir / "made.png";
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(made.data()),
                                                 static_cast<std::streamsize>(made.size()));
    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    ASSERT_EQ(spec.width, c.w);
    ASSERT_EQ(spec.height, c.h);
    ASSERT_EQ(spec.nchannels, 3);
    EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(spec.get_string_attribute("oiio:ColorSpace"), "sRGB") << c.w << "x" << c.h;
    std::vector<std::uint8_t> back(rgb.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, back.data()));
    EXPECT_TRUE(back == rgb) << c.w << "x" << c.h << " content " << static_cast<int>(c.content);
  }
}

// The libpng the frames' bytes were fixed to (Debian 12's, through
// OpenImageIO 2.4): the encoder reproduces its bytes, so frames keep the
// bytes they had when OpenImageIO wrote them.  With another libpng or
// OpenImageIO (Debian 13's) the writer's bytes are not this test's to pin:
// skipped, and ReadsBackAsItsPixels still holds.
TEST(PngEncoder, MakesOpenImageIosBytes) {
  const std::string libraries = OIIO::get_string_attribute("library_list");
  if (libraries.find("png:libpng 1.6.39") == std::string::npos || OIIO::openimageio_version() / 100 != 204)
    GTEST_SKIP() << "the bytes are pinned to OpenImageIO 2.4 with libpng 1.6.39; this one is OpenImageIO "
                 << OIIO::openimageio_version() << " with " << libraries;
  test::ScratchDir dir;
  for (const Case& c : cases()) {
    const std::vector<std::uint8_t> rgb = pixels(c.w, c.h, c.content, c.seed);
    const std::vector<unsigned char> expected = oiio_png(dir / "oiio.png", rgb, c.w, c.h);
    const std::vector<unsigned char> made = encode_png8(rgb, c.w, c.h);
    EXPECT_EQ(made.size(), expected.size()) << c.w << "x" << c.h << " content " << static_cast<int>(c.content);
    EXPECT_TRUE(made == expected) << c.w << "x" << c.h << " content " << static_cast<int>(c.content);
  }
}

TEST(PngEncoder, RefusesASizeThatDoesNotMatch) {
  const std::vector<std::uint8_t> rgb(3 * 4 * 4);
  EXPECT_THROW(encode_png8(rgb, 4, 5), std::invalid_argument);
  EXPECT_THROW(encode_png8(rgb, 0, 16), std::invalid_argument);
  EXPECT_NO_THROW(encode_png8(rgb, 4, 4));
}

}  // namespace
}  // namespace lc
