// Tests of the image layer's files and textures: EXR frames round trip bit
// for bit (layers, metadata), PNG encodes the sRGB curve, formats follow the
// function and not the file name, errors name the file, and Texture reads,
// decodes and samples correctly.  Test images are written with OpenImageIO
// directly where the image layer itself cannot make them (16-bit, grey,
// alpha, oversized).

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image.hpp"
#include "png_rules.hpp"
#include "scratch_dir.hpp"
#include "test_errors.hpp"

namespace {

namespace fs = std::filesystem;
using lc::FrameImage;
using lc::Texture;

using lc::test::error_of;
using lc::test::ScratchDir;

// The first bytes of a file (its format's magic number).
std::string head_bytes(const fs::path& p, std::size_t n) {
  std::ifstream in(p, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), static_cast<std::streamsize>(n));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

std::string file_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

const std::string kExrMagic("\x76\x2f\x31\x01", 4);
const std::string kPngMagic("\x89PNG\r\n\x1a\n", 8);

// Bitwise equality of float arrays (NaN payloads and -0 included).
bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// A w x h frame whose RGB is a smooth ramp, no layers.
FrameImage ramp(int w, int h) {
  FrameImage im;
  im.width = w;
  im.height = h;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      im.rgb.push_back(static_cast<float>(i) / static_cast<float>(w));
      im.rgb.push_back(static_cast<float>(j) / static_cast<float>(h));
      im.rgb.push_back(0.25f);
    }
  return im;
}

// Writes an image of `type` with `channels` per pixel straight through
// OpenImageIO (format from the extension), values given as floats in [0, 1]
// and stored as given (a 4th channel is unassociated alpha, as in PNG).
void write_with_oiio(const fs::path& p, int w, int h, int channels, OIIO::TypeDesc type,
                     const std::vector<float>& values) {
  OIIO::ImageSpec spec(w, h, channels, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  auto out = OIIO::ImageOutput::create(p.string());
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(p.string(), spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, values.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// ---------------------------------------------------------------- EXR ----

TEST(ImageIo, ExrRoundTripIsBitExactWithLayersAndMetadata) {
  ScratchDir dir;
  const int w = 7, h = 5, n = w * h;
  FrameImage im;
  im.width = w;
  im.height = h;
  // Values half floats or lossy compression would change, and special ones.
  const std::array<float, 8> special = {0.1f,
                                        -0.0f,
                                        1e-40f /* denormal */,
                                        3.0e38f,
                                        -2.5f,
                                        1.0f / 3.0f,
                                        std::numeric_limits<float>::infinity(),
                                        std::numeric_limits<float>::quiet_NaN()};
  for (int k = 0; k < 3 * n; ++k)
    im.rgb.push_back(k < 8 ? special[static_cast<std::size_t>(k)] : 0.001f * static_cast<float>(k * k) + 1e-7f);
  std::vector<float> kind(n), r(n), order(n);
  for (int p = 0; p < n; ++p) {
    kind[p] = static_cast<float>(p % 5);
    r[p] = 2.0f + std::sqrt(static_cast<float>(p)) / 7.0f;
    order[p] = -static_cast<float>(p);
  }
  im.layers = {{"hit.kind", kind}, {"hit.r", r}, {"order", order}};
  const fs::path file = dir / "frame.0001.exr";
  lc::write_exr(file, im, {{"lightcone/shot", "kerr_disk"}, {"lightcone/frame", "12"}});

  const FrameImage back = lc::read_exr(file);
  EXPECT_EQ(back.width, w);
  EXPECT_EQ(back.height, h);
  EXPECT_TRUE(same_bits(back.rgb, im.rgb));
  ASSERT_EQ(back.layers.size(), 3u);
  for (const FrameImage::Layer& l : im.layers) {
    bool found = false;
    for (const FrameImage::Layer& b : back.layers)
      if (b.name == l.name) {
        found = true;
        EXPECT_TRUE(same_bits(b.values, l.values)) << l.name;
      }
    EXPECT_TRUE(found) << "layer " << l.name << " lost";
  }

  const lc::ImageMetadata meta = lc::read_exr_metadata(file);
  auto value_of = [&](const std::string& key) {
    for (const auto& [k, v] : meta)
      if (k == key) return v;
    return std::string("<missing>");
  };
  EXPECT_EQ(value_of("lightcone/shot"), "kerr_disk");
  EXPECT_EQ(value_of("lightcone/frame"), "12");
  EXPECT_EQ(value_of("compression"), "zip");
  EXPECT_EQ(value_of("DateTime"), "<missing>");  // no timestamp: reproducible bytes

  // The same frame written again is the same file.
  const fs::path again = dir / "frame.0001.exr.again";
  lc::write_exr(again, im, {{"lightcone/shot", "kerr_disk"}, {"lightcone/frame", "12"}});
  EXPECT_EQ(file_bytes(again), file_bytes(file));

  // Every channel stored as 32-bit float, straight from the file's header.
  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().nchannels, 6);
  EXPECT_EQ(in->spec().format, OIIO::TypeDesc::FLOAT);
  for (const OIIO::TypeDesc& t : in->spec().channelformats) EXPECT_EQ(t, OIIO::TypeDesc::FLOAT);
}

// A frame with pixels the camera had no ray through (a dome master's
// corners) carries them as alpha; an opaque one's file is the file it was
// before alpha existed: no A channel, the same bytes as with no alpha.
TEST(ImageIo, ExrHasAnAlphaChannelOnlyWhereSomePixelIsNotOpaque) {
  ScratchDir dir;
  FrameImage opaque = ramp(4, 3);
  opaque.layers = {{"hit.kind", std::vector<float>(12, 2.0f)}};
  lc::write_exr(dir / "none.exr", opaque);
  opaque.alpha.assign(12, 1.0f);
  lc::write_exr(dir / "opaque.exr", opaque);
  EXPECT_EQ(file_bytes(dir / "opaque.exr"), file_bytes(dir / "none.exr"));
  EXPECT_TRUE(lc::read_exr(dir / "opaque.exr").alpha.empty());

  FrameImage dome = opaque;
  dome.alpha[0] = 0.0f;
  dome.alpha[5] = 0.75f;
  lc::write_exr(dir / "dome.exr", dome);
  const FrameImage back = lc::read_exr(dir / "dome.exr");
  EXPECT_TRUE(same_bits(back.alpha, dome.alpha));
  EXPECT_TRUE(same_bits(back.rgb, dome.rgb));
  ASSERT_EQ(back.layers.size(), 1u);  // A is alpha, not a data layer
  EXPECT_EQ(back.layers[0].name, "hit.kind");
  auto in = OIIO::ImageInput::open((dir / "dome.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().alpha_channel, 3);  // R, G, B, A as readers expect them
  EXPECT_EQ(in->spec().channelnames[3], "A");

  FrameImage short_alpha = dome;
  short_alpha.alpha.pop_back();
  EXPECT_NE(error_of([&] { lc::write_exr(dir / "bad.exr", short_alpha); }).find("alpha holds 11"), std::string::npos);
  FrameImage clash = opaque;
  clash.layers = {{"A", std::vector<float>(12)}};
  EXPECT_NE(error_of([&] { lc::write_exr(dir / "bad.exr", clash); }).find("clashes with R, G, B, A"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "bad.exr"));
}

TEST(ImageIo, ExrRefusesInconsistentFramesAndReservedMetadata) {
  ScratchDir dir;
  const fs::path file = dir / "bad.exr";
  FrameImage im = ramp(4, 3);

  FrameImage short_rgb = im;
  short_rgb.rgb.pop_back();
  EXPECT_NE(error_of([&] { lc::write_exr(file, short_rgb); }).find("rgb holds 35 floats"), std::string::npos);

  FrameImage dup = im;
  dup.layers = {{"hit.r", std::vector<float>(12)}, {"hit.r", std::vector<float>(12)}};
  EXPECT_NE(error_of([&] { lc::write_exr(file, dup); }).find("'hit.r' is used twice"), std::string::npos);

  FrameImage clash = im;
  clash.layers = {{"G", std::vector<float>(12)}};
  EXPECT_NE(error_of([&] { lc::write_exr(file, clash); }).find("clashes with R, G, B, A"), std::string::npos);

  FrameImage short_layer = im;
  short_layer.layers = {{"hit.t", std::vector<float>(11)}};
  EXPECT_NE(error_of([&] { lc::write_exr(file, short_layer); }).find("'hit.t' holds 11"), std::string::npos);

  FrameImage empty;
  EXPECT_NE(error_of([&] { lc::write_exr(file, empty); }).find("zero-size"), std::string::npos);

  EXPECT_NE(error_of([&] { lc::write_exr(file, im, {{"compression", "dwaa"}}); }).find("reserved"), std::string::npos);
  EXPECT_NE(error_of([&] {
              lc::write_exr(file, im, {{"openexr:lineOrder", "x"}});
            }).find("reserved"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(file));
}

TEST(ImageIo, ReadExrRefusesOtherFiles) {
  ScratchDir dir;
  const fs::path png = dir / "frame.png";
  lc::write_png(png, ramp(4, 4));
  std::string msg = error_of([&] { lc::read_exr(png); });
  EXPECT_NE(msg.find(png.string()), std::string::npos) << msg;

  const fs::path missing = dir / "missing.exr";
  msg = error_of([&] { lc::read_exr(missing); });
  EXPECT_NE(msg.find(missing.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;
}

// ---------------------------------------------------------------- PNG ----

TEST(ImageIo, SrgbCurveIsTheStandardOne) {
  EXPECT_EQ(lc::linear_to_srgb8(0.0f), 0);
  EXPECT_EQ(lc::linear_to_srgb8(1.0f), 255);
  EXPECT_NEAR(lc::linear_to_srgb8(0.214f), 128, 1);
  EXPECT_EQ(lc::linear_to_srgb8(0.5f), 188);  // a pure 2.2 gamma would give 186
  EXPECT_EQ(lc::linear_to_srgb8(0.001f), 3);  // linear toe: 12.92 * 0.001 * 255 = 3.3
  EXPECT_EQ(lc::linear_to_srgb8(7.5f), 255);
  EXPECT_EQ(lc::linear_to_srgb8(-1.0f), 0);
  EXPECT_EQ(lc::linear_to_srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
  EXPECT_NEAR(lc::srgb8_to_linear(128), 0.2158605f, 1e-6f);
  for (int k = 0; k < 256; ++k)
    EXPECT_EQ(lc::linear_to_srgb8(lc::srgb8_to_linear(static_cast<std::uint8_t>(k))), k) << k;
}

TEST(ImageIo, PngStoresSrgbCodes) {
  ScratchDir dir;
  FrameImage im;
  im.width = 3;
  im.height = 2;
  im.rgb = {0.214f, 0.0f, 1.0f, /**/ 5.0f, -0.5f, 0.5f, /**/ 0.001f, 0.02f,  0.9f,
            0.0f,   0.0f, 0.0f, /**/ 1.0f, 1.0f,  1.0f, /**/ 0.214f, 0.214f, 0.214f};
  im.layers = {{"hit.kind", std::vector<float>(6, 1.0f)}};  // ignored by PNG
  const fs::path file = dir / "frame.png";
  lc::write_png(file, im);

  // The codes as stored, read with OIIO directly.
  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in);
  ASSERT_EQ(in->spec().nchannels, 3);
  ASSERT_EQ(in->spec().format, OIIO::TypeDesc::UINT8);
  std::vector<std::uint8_t> codes(18);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, codes.data()));
  // 0.214 is sRGB 127.49 (the "128 +- 1" of the spec), 0.02 is 38.7, 0.9 is 243.4.
  const std::vector<int> expect = {127, 0, 255, 255, 0, 188, 3, 39, 243, 0, 0, 0, 255, 255, 255, 127, 127, 127};
  for (std::size_t k = 0; k < codes.size(); ++k) EXPECT_EQ(codes[k], expect[k]) << k;

  // And read back as linear: the decoded code values.
  const FrameImage back = lc::read_image_linear(file);
  ASSERT_EQ(back.rgb.size(), 18u);
  for (std::size_t k = 0; k < codes.size(); ++k) EXPECT_EQ(back.rgb[k], lc::srgb8_to_linear(codes[k])) << k;
  EXPECT_TRUE(back.layers.empty());
}

// At either depth (8 bits: png_encoder.hpp, or OpenImageIO's writer in a
// build without lightcone's own codecs; 16: OpenImageIO's writer) the PNG
// keeps the format's rules (png_rules.hpp), is tagged sRGB, and libpng
// decodes every pixel to the code srgb.hpp gives its colour.  Sizes odd on
// purpose.
TEST(ImageIo, PngKeepsTheRulesAndDecodesToItsCodesAtEitherDepth) {
  ScratchDir dir;
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {7, 5}, {33, 17}, {1, 9}, {129, 3}}) {
    FrameImage im = ramp(w, h);
    for (std::size_t k = 0; k < im.rgb.size(); k += 7) im.rgb[k] = 1.7f * static_cast<float>(k % 5) - 0.2f;
    for (const lc::PngDepth depth : {lc::PngDepth::eight, lc::PngDepth::sixteen}) {
      const int bits = static_cast<int>(depth);
      const std::string at = std::to_string(w) + "x" + std::to_string(h) + " at " + std::to_string(bits) + " bits";
      const fs::path file = dir / "frame.png";
      lc::write_png(file, im, {}, depth);
      std::vector<lc::test::PngChunk> chunks;
      EXPECT_EQ(lc::test::png_rule_broken(file_bytes(file),
                                          {static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h), bits, 2}, &chunks),
                "")
          << at;
      bool srgb = false;
      for (const lc::test::PngChunk& c : chunks) srgb |= c.type == "sRGB";
      EXPECT_TRUE(srgb) << at;

      auto in = OIIO::ImageInput::open(file.string());
      ASSERT_TRUE(in) << OIIO::geterror();
      ASSERT_EQ(in->spec().nchannels, 3) << at;
      std::vector<std::uint16_t> codes(im.rgb.size());
      if (depth == lc::PngDepth::sixteen) {
        ASSERT_EQ(in->spec().format, OIIO::TypeDesc::UINT16) << at;
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, codes.data())) << at;
      } else {
        ASSERT_EQ(in->spec().format, OIIO::TypeDesc::UINT8) << at;
        std::vector<std::uint8_t> bytes(im.rgb.size());
        ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, bytes.data())) << at;
        codes.assign(bytes.begin(), bytes.end());
      }
      for (std::size_t k = 0; k < codes.size(); ++k) {
        const int want = depth == lc::PngDepth::sixteen ? lc::linear_to_srgb16(im.rgb[k]) : lc::linear_to_srgb8(im.rgb[k]);
        ASSERT_EQ(codes[k], want) << at << ", value " << k;
      }
    }
  }
}

// ------------------------------------------------------ files and names ----

TEST(ImageIo, WritingIntoMissingDirectoryThrowsNamingThePath) {
  ScratchDir dir;
  const fs::path exr = dir / "no/such/dir/frame.0001.exr";
  const fs::path png = dir / "no/such/dir/frame.0001.png";
  std::string msg = error_of([&] { lc::write_exr(exr, ramp(4, 4)); });
  EXPECT_NE(msg.find(exr.string()), std::string::npos) << msg;
  msg = error_of([&] { lc::write_png(png, ramp(4, 4)); });
  EXPECT_NE(msg.find(png.string()), std::string::npos) << msg;
  EXPECT_FALSE(fs::exists(dir / "no"));
}

TEST(ImageIo, FormatFollowsTheFunctionNotTheFileName) {
  ScratchDir dir;
  const FrameImage im = ramp(8, 4);
  const fs::path exr_tmp = dir / "frame.0001.exr.tmp-123";
  const fs::path png_tmp = dir / "frame.0001.png.tmp-123";
  const fs::path exr_as_png = dir / "misnamed.png";
  const fs::path png_as_txt = dir / "misnamed.txt";
  lc::write_exr(exr_tmp, im);
  lc::write_png(png_tmp, im);
  lc::write_exr(exr_as_png, im);
  lc::write_png(png_as_txt, im);
  EXPECT_EQ(head_bytes(exr_tmp, 4), kExrMagic);
  EXPECT_EQ(head_bytes(exr_as_png, 4), kExrMagic);
  EXPECT_EQ(head_bytes(png_tmp, 8), kPngMagic);
  EXPECT_EQ(head_bytes(png_as_txt, 8), kPngMagic);

  // Readers look at the content: a renamed-later temp file reads back.
  EXPECT_TRUE(same_bits(lc::read_exr(exr_tmp).rgb, im.rgb));
  EXPECT_TRUE(same_bits(lc::read_exr(exr_as_png).rgb, im.rgb));
  EXPECT_EQ(lc::read_image_linear(png_tmp).width, 8);
  EXPECT_EQ(lc::read_image_linear(png_as_txt).height, 4);
}

TEST(ImageIo, ReadImageLinearKeepsFloatExrLinear) {
  ScratchDir dir;
  const FrameImage im = ramp(5, 3);
  const fs::path file = dir / "linear.exr";
  lc::write_exr(file, im);
  EXPECT_TRUE(same_bits(lc::read_image_linear(file).rgb, im.rgb));
}

TEST(ImageIo, ImageSizeReadsTheHeaderOnly) {
  ScratchDir dir;
  const fs::path png = dir / "frame.png";
  lc::write_png(png, ramp(8, 4));
  EXPECT_EQ(lc::image_size(png), std::make_pair(8, 4));
  // The same file cut off inside its pixel data: the size is still known
  // (no pixel was decoded), reading the pixels fails.
  std::ifstream in(png, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t data = bytes.find("IDAT");  // the first chunk of pixel data, after the header chunks
  ASSERT_NE(data, std::string::npos);
  const fs::path cut = dir / "cut.png";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, data + 6);
  EXPECT_EQ(lc::image_size(cut), std::make_pair(8, 4));
  EXPECT_THROW(lc::read_image_linear(cut), std::runtime_error);
  EXPECT_NE(error_of([&] { lc::image_size(dir / "none.png"); }).find("none.png': no such file"), std::string::npos);
}

// ------------------------------------------------------------ Texture ----

TEST(Texture, LoadErrorsNameTheFileAndTheReason) {
  ScratchDir dir;
  const fs::path missing = dir / "missing_sky.png";
  std::string msg = error_of([&] { Texture::load(missing); });
  EXPECT_NE(msg.find(missing.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("no such file"), std::string::npos) << msg;

  const fs::path text = dir / "sky.png";  // a text file with an image's name
  std::ofstream(text) << "this is not an image\n";
  msg = error_of([&] { Texture::load(text); });
  EXPECT_NE(msg.find(text.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("not an image"), std::string::npos) << msg;

  const fs::path folder = dir / "folder.png";
  fs::create_directory(folder);
  msg = error_of([&] { Texture::load(folder); });
  EXPECT_NE(msg.find("directory"), std::string::npos) << msg;

  const fs::path huge = dir / "huge.png";  // 40000 x 1: compresses to almost nothing
  write_with_oiio(huge, 40000, 1, 1, OIIO::TypeDesc::UINT8, std::vector<float>(40000, 0.5f));
  msg = error_of([&] { Texture::load(huge); });
  EXPECT_NE(msg.find(huge.string()), std::string::npos) << msg;
  EXPECT_NE(msg.find("too large"), std::string::npos) << msg;

  // A pixel budget (a shot's sky images: docs/shots.md, Limits) is checked
  // from the header, before the pixels are read.
  const fs::path wide = dir / "wide.png";
  write_with_oiio(wide, 300, 100, 1, OIIO::TypeDesc::UINT8, std::vector<float>(30000, 0.5f));
  msg = error_of([&] { Texture::load(wide, 20000); });
  EXPECT_NE(msg.find("image too large (300 x 100; at most 20000 pixels, e.g. 200 x 100"), std::string::npos) << msg;
  EXPECT_EQ(Texture::load(wide, 30000).width(), 300);
}

TEST(Texture, FromPixelsChecksItsInput) {
  EXPECT_THROW(Texture::from_pixels(0, 1, {}), std::invalid_argument);
  EXPECT_THROW(Texture::from_pixels(2, 1, std::vector<float>(5)), std::invalid_argument);
  const Texture t = Texture::from_pixels(2, 1, std::vector<float>(6, 0.5f));
  EXPECT_EQ(t.width(), 2);
  EXPECT_EQ(t.height(), 1);
}

// A 4 x 2 texture: texel (i, j) has red = i, green = j, blue = 10 i + j.
Texture grid_texture() {
  std::vector<float> rgb;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) {
      rgb.push_back(static_cast<float>(i));
      rgb.push_back(static_cast<float>(j));
      rgb.push_back(static_cast<float>(10 * i + j));
    }
  return Texture::from_pixels(4, 2, std::move(rgb));
}

std::array<float, 3> at(const Texture& t, double u, double v) {
  std::array<float, 3> c{};
  t.sample(u, v, c.data());
  return c;
}

TEST(Texture, SampleHitsTexelCentresAndMidpointsExactly) {
  const Texture t = grid_texture();
  // Texel (i, j) centre: u = (i + 0.5) / 4, v = (j + 0.5) / 2.
  EXPECT_EQ(at(t, 2.5 / 4, 1.5 / 2), (std::array<float, 3>{2.0f, 1.0f, 21.0f}));
  // Halfway between texels 1 and 2 of row 0: the mean.
  EXPECT_EQ(at(t, 2.0 / 4, 0.5 / 2), (std::array<float, 3>{1.5f, 0.0f, 15.0f}));
  // The centre of four texels (1..2, 0..1).
  EXPECT_EQ(at(t, 2.0 / 4, 0.5), (std::array<float, 3>{1.5f, 0.5f, 15.5f}));
  // A quarter of the way: bilinear, not nearest.
  EXPECT_EQ(at(t, 1.75 / 4, 0.5 / 2), (std::array<float, 3>{1.25f, 0.0f, 12.5f}));
}

TEST(Texture, SampleWrapsInU) {
  const Texture t = grid_texture();
  for (double u : {0.1, 0.37, 0.6, 0.99}) {
    EXPECT_EQ(at(t, u, 0.3), at(t, u + 1.0, 0.3)) << u;
    EXPECT_EQ(at(t, u, 0.3), at(t, u - 3.0, 0.3)) << u;
  }
  // u = 0 is the seam between the last and the first column.
  EXPECT_EQ(at(t, 0.0, 0.25), (std::array<float, 3>{1.5f, 0.0f, 15.0f}));
  EXPECT_EQ(at(t, 1.0, 0.25), at(t, 0.0, 0.25));
  EXPECT_EQ(at(t, -1e-20, 0.25), at(t, 0.0, 0.25));
  // A quarter texel left of the seam is mostly the last column.
  EXPECT_EQ(at(t, -0.25 / 4, 0.25), (std::array<float, 3>{2.25f, 0.0f, 22.5f}));
}

TEST(Texture, SampleClampsInV) {
  const Texture t = grid_texture();
  const std::array<float, 3> top = at(t, 1.5 / 4, 0.25), bottom = at(t, 1.5 / 4, 0.75);
  EXPECT_EQ(top, (std::array<float, 3>{1.0f, 0.0f, 10.0f}));
  EXPECT_EQ(bottom, (std::array<float, 3>{1.0f, 1.0f, 11.0f}));
  for (double v : {0.0, 0.1, -0.5, -1e9}) EXPECT_EQ(at(t, 1.5 / 4, v), top) << v;
  for (double v : {1.0, 0.9, 1.5, 1e9}) EXPECT_EQ(at(t, 1.5 / 4, v), bottom) << v;
  // Non-finite coordinates stay inside the texture.
  const std::array<float, 3> c = at(t, std::nan(""), std::nan(""));
  for (float x : c) EXPECT_TRUE(std::isfinite(x));
}

TEST(Texture, EightBitSrgbIsDecodedToLinear) {
  ScratchDir dir;
  const fs::path file = dir / "sky.png";
  // Codes 0, 64, 128, 255 in red; green and blue fixed.
  const std::vector<float> values = {0.0f,         1.0f, 0.5f, 64 / 255.0f, 1.0f, 0.5f,
                                     128 / 255.0f, 1.0f, 0.5f, 1.0f,        1.0f, 0.5f};
  write_with_oiio(file, 4, 1, 3, OIIO::TypeDesc::UINT8, values);
  const Texture t = Texture::load(file);
  ASSERT_EQ(t.width(), 4);
  ASSERT_EQ(t.height(), 1);
  EXPECT_EQ(at(t, 0.5 / 4, 0.5)[0], 0.0f);
  EXPECT_NEAR(at(t, 1.5 / 4, 0.5)[0], 0.0512695, 1e-6);
  EXPECT_NEAR(at(t, 2.5 / 4, 0.5)[0], 0.2158605, 1e-6);
  EXPECT_EQ(at(t, 3.5 / 4, 0.5)[0], 1.0f);
  EXPECT_EQ(at(t, 3.5 / 4, 0.5)[1], 1.0f);
  EXPECT_NEAR(at(t, 3.5 / 4, 0.5)[2], 0.2158605, 1e-6);  // code 128 again (0.5 * 255 rounds up)
}

TEST(Texture, SixteenBitGreyAndAlphaAreHandled) {
  ScratchDir dir;
  // 16-bit sRGB: decoded with the full curve, not by 8-bit codes.
  const fs::path deep = dir / "deep.png";
  write_with_oiio(deep, 1, 1, 3, OIIO::TypeDesc::UINT16, {32768 / 65535.0f, 16384 / 65535.0f, 1.0f});
  const std::array<float, 3> c = at(Texture::load(deep), 0.5, 0.5);
  EXPECT_NEAR(c[0], lc::srgb_to_linear(32768 / 65535.0), 1e-6);
  EXPECT_NEAR(c[1], lc::srgb_to_linear(16384 / 65535.0), 1e-6);
  EXPECT_EQ(c[2], 1.0f);

  // Grey: one channel copied to R, G, B.
  const fs::path grey = dir / "grey.png";
  write_with_oiio(grey, 1, 1, 1, OIIO::TypeDesc::UINT8, {128 / 255.0f});
  const std::array<float, 3> g = at(Texture::load(grey), 0.5, 0.5);
  EXPECT_NEAR(g[0], 0.2158605, 1e-6);
  EXPECT_EQ(g[0], g[1]);
  EXPECT_EQ(g[0], g[2]);

  // RGBA (unassociated in PNG): colour decoded, then composited over black.
  const fs::path rgba = dir / "rgba.png";
  write_with_oiio(rgba, 1, 1, 4, OIIO::TypeDesc::UINT8, {1.0f, 128 / 255.0f, 0.0f, 51 / 255.0f});
  const std::array<float, 3> a = at(Texture::load(rgba), 0.5, 0.5);
  EXPECT_NEAR(a[0], 0.2, 1e-6);
  EXPECT_NEAR(a[1], 0.2 * 0.2158605, 1e-6);
  EXPECT_EQ(a[2], 0.0f);
}

TEST(Texture, FloatImagesAreLinear) {
  ScratchDir dir;
  const fs::path exr = dir / "sky.exr";
  FrameImage im = ramp(4, 2);
  im.rgb[0] = 0.5f;
  im.rgb[1] = 3.0f;  // HDR values pass through unclamped
  lc::write_exr(exr, im);
  const Texture t = Texture::load(exr);
  const std::array<float, 3> c = at(t, 0.5 / 4, 0.25);
  EXPECT_EQ(c[0], 0.5f);
  EXPECT_EQ(c[1], 3.0f);
  EXPECT_EQ(c[2], 0.25f);

  // A half-float EXR written by another tool reads the same way.
  const fs::path half = dir / "half.exr";
  write_with_oiio(half, 1, 1, 3, OIIO::TypeDesc::HALF, {0.5f, 0.25f, 2.0f});
  EXPECT_EQ(at(Texture::load(half), 0.5, 0.5), (std::array<float, 3>{0.5f, 0.25f, 2.0f}));
}

}  // namespace
