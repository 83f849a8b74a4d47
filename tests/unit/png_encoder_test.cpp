// The 8-bit PNG encoder (image/png_encoder.hpp) makes the very bytes
// OpenImageIO's PNG writer (libpng) makes for the same pixels: for every
// shape libpng treats apart (one pixel, one row, one column, images small
// enough for a smaller zlib window and just too large for it, several
// IDAT chunks) and content that exercises each filter (smooth ramps, flat
// colour where filters tie, noise, hard edges).  The frames' PNGs so stay
// what they were when OpenImageIO wrote them.

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

TEST(PngEncoder, MakesOpenImageIosBytes) {
  test::ScratchDir dir;
  // 5x1024 and 48x113: 16,384 and 16,385 bytes filtered, either side of
  // libpng's smaller window.
  const std::vector<std::pair<int, int>> shapes = {{1, 1},   {1, 9},   {9, 1},    {2, 2},    {5, 3},
                                                   {33, 17}, {64, 64}, {73, 74},  {75, 75},  {5, 1024},
                                                   {48, 113}, {1, 4097}, {5461, 1}, {200, 150}, {640, 360}};
  unsigned seed = 1;
  for (const auto& [w, h] : shapes)
    for (const Content content : {Content::ramp, Content::flat, Content::noise, Content::edges, Content::mixed}) {
      const std::vector<std::uint8_t> rgb = pixels(w, h, content, seed++);
      const std::vector<unsigned char> expected = oiio_png(dir / "oiio.png", rgb, w, h);
      const std::vector<unsigned char> made = encode_png8(rgb, w, h);
      EXPECT_EQ(made.size(), expected.size()) << w << "x" << h << " content " << static_cast<int>(content);
      EXPECT_TRUE(made == expected) << w << "x" << h << " content " << static_cast<int>(content);
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
