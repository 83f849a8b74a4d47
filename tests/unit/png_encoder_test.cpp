// The 8-bit PNG encoder (image/png_encoder.hpp) makes PNGs that keep the
// format's rules (tests/unit/png_rules.hpp: chunks, CRCs, IHDR, the zlib
// stream, the sRGB tags) and that libpng decodes to the very pixels given:
// for every shape the encoder treats apart (one pixel, one row, one column,
// odd sizes, images small enough for a smaller zlib window and just too
// large for it, several IDAT chunks) and content that exercises each filter
// (smooth ramps, flat colour where filters tie, noise, hard edges).  Held
// to the format and the pixels, not to another writer's bytes, so a new
// libpng or OpenImageIO cannot turn it red.

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "image/png_encoder.hpp"
#include "file_bytes.hpp"
#include "png_rules.hpp"
#include "scratch_dir.hpp"

namespace lc {
namespace {

namespace fs = std::filesystem;

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

// The shapes and contents the tests below go through.
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

// The file as written, and the pixels libpng (through OpenImageIO's reader)
// decodes from it, 8-bit RGB.
struct Decoded {
  std::string bytes;
  OIIO::ImageSpec spec;
  std::vector<std::uint8_t> rgb;
};
Decoded decode(const fs::path& file, const std::vector<unsigned char>& made) {
  Decoded d;
  d.bytes.assign(made.begin(), made.end());
  test::put(file, d.bytes);
  auto in = OIIO::ImageInput::open(file.string());
  EXPECT_TRUE(in) << OIIO::geterror();
  if (!in) return d;
  d.spec = in->spec();
  d.rgb.resize(3 * static_cast<std::size_t>(d.spec.width) * static_cast<std::size_t>(d.spec.height));
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, d.rgb.data())) << in->geterror();
  return d;
}

// Every PNG made keeps the format's rules (png_rules.hpp) and decodes, every
// pixel, to the codes it was given.
TEST(PngEncoder, KeepsThePngRulesAndDecodesToItsPixels) {
  test::ScratchDir dir;
  for (const Case& c : cases()) {
    const std::vector<std::uint8_t> rgb = pixels(c.w, c.h, c.content, c.seed);
    const Decoded d = decode(dir / "made.png", encode_png8(rgb, c.w, c.h));
    const std::string at = std::to_string(c.w) + "x" + std::to_string(c.h) + " content " +
                           std::to_string(static_cast<int>(c.content));
    EXPECT_EQ(test::png_rule_broken(d.bytes, {static_cast<std::uint32_t>(c.w), static_cast<std::uint32_t>(c.h), 8, 2}), "")
        << at;
    ASSERT_EQ(d.spec.width, c.w) << at;
    ASSERT_EQ(d.spec.height, c.h) << at;
    ASSERT_EQ(d.spec.nchannels, 3) << at;
    EXPECT_EQ(d.spec.format, OIIO::TypeDesc::UINT8) << at;
    EXPECT_EQ(d.spec.get_string_attribute("oiio:ColorSpace"), "sRGB") << at;
    EXPECT_TRUE(d.rgb == rgb) << at;
  }
}

// The ancillary chunks it writes, in order, and what they hold: the file
// tagged sRGB as OpenImageIO tags an sRGB image (png_encoder.hpp).
TEST(PngEncoder, TagsTheFileSrgb) {
  const std::vector<std::uint8_t> rgb = pixels(5, 3, Content::ramp, 1);
  const std::vector<unsigned char> made = encode_png8(rgb, 5, 3);
  std::vector<test::PngChunk> chunks;
  ASSERT_EQ(test::png_rule_broken(std::string(made.begin(), made.end()), {5, 3, 8, 2}, &chunks), "");
  std::vector<std::string> types;
  for (const test::PngChunk& c : chunks) types.push_back(c.type);
  EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "gAMA", "sRGB", "cHRM", "oFFs", "tEXt", "IDAT", "IEND"}));
  ASSERT_EQ(chunks.size(), 8u);
  EXPECT_EQ(chunks[2].data, std::string(1, '\3'));                   // absolute colorimetric
  EXPECT_EQ(chunks[4].data, std::string(9, '\0'));                   // offset 0, 0 in pixels
  EXPECT_EQ(chunks[5].data, std::string("oiio:ColorSpace\0sRGB", 20));
}

// The rules above can fail: each of these breaks in a made file is named.
TEST(PngEncoder, RulesCatchABrokenFile) {
  const std::vector<std::uint8_t> rgb = pixels(33, 17, Content::mixed, 7);
  const std::vector<unsigned char> made = encode_png8(rgb, 33, 17);
  const std::string good(made.begin(), made.end());
  const test::PngHeader header{33, 17, 8, 2};
  ASSERT_EQ(test::png_rule_broken(good, header), "");
  // Offsets: IHDR's data at 16; gAMA's chunk after IHDR's 25 bytes.
  const std::size_t ihdr_data = 16, gama = 8 + 25, iend = good.size() - 12;
  // A chunk rebuilt whole, its CRC right, so the rule after the CRC shows.
  const auto chunk = [](const std::string& type, const std::string& data) {
    std::string c;
    for (int shift = 24; shift >= 0; shift -= 8) c += static_cast<char>((data.size() >> shift) & 0xff);
    c += type + data;
    const std::uint32_t crc = test::png_crc(type, data);
    for (int shift = 24; shift >= 0; shift -= 8) c += static_cast<char>((crc >> shift) & 0xff);
    return c;
  };
  std::string s = good;
  s[iend - 1] ^= 1;  // the last IDAT's CRC
  EXPECT_NE(test::png_rule_broken(s, header).find("CRC wrong"), std::string::npos);
  s = good;
  s.erase(iend);
  EXPECT_EQ(test::png_rule_broken(s, header), "no IEND");
  s = good + "x";
  EXPECT_EQ(test::png_rule_broken(s, header), "1 bytes after IEND");
  s = good;
  s.replace(ihdr_data - 8, 25, chunk("IHDR", good.substr(ihdr_data, 8) + std::string("\x10\2\0\0\0", 5)));
  EXPECT_EQ(test::png_rule_broken(s, header), "IHDR: bit depth 16");
  s = good;
  s.replace(gama, 16, chunk("gAMA", std::string("\0\1\0\0", 4)));
  EXPECT_EQ(test::png_rule_broken(s, header), "gAMA: not sRGB's 45455 beside sRGB");
  s = good;
  s.insert(iend, chunk("gAMA", good.substr(gama + 8, 4)));  // a second gAMA, after IDAT
  EXPECT_EQ(test::png_rule_broken(s, header), "gAMA after IDAT");
  // The only IDAT with one byte of its stream changed, its CRC made right.
  const std::size_t idat = good.rfind("IDAT", iend) - 4;
  const std::string data = good.substr(idat + 8, iend - idat - 12);
  std::string changed = data;
  changed[changed.size() - 2] ^= 0x40;  // the Adler-32 at the stream's end
  s = good;
  s.replace(idat, iend - idat, chunk("IDAT", changed));
  EXPECT_NE(test::png_rule_broken(s, header).find("not one whole zlib stream"), std::string::npos);
  s = good;
  s.replace(idat, iend - idat, chunk("IDAT", data) + chunk("tEXt", std::string("a\0b", 3)) + chunk("IDAT", ""));
  EXPECT_EQ(test::png_rule_broken(s, header), "IDAT chunks not consecutive");
  EXPECT_EQ(test::png_rule_broken(good, {34, 17, 8, 2}), "IHDR: another size");
}

TEST(PngEncoder, RefusesASizeThatDoesNotMatch) {
  const std::vector<std::uint8_t> rgb(3 * 4 * 4);
  EXPECT_THROW(encode_png8(rgb, 4, 5), std::invalid_argument);
  EXPECT_THROW(encode_png8(rgb, 0, 16), std::invalid_argument);
  EXPECT_NO_THROW(encode_png8(rgb, 4, 4));
}

}  // namespace
}  // namespace lc
