// The direct reader of lightcone's own EXR layout (image/exr_rgb_reader.hpp):
// it gives back bit for bit what write_exr wrote (RGB and RGBA, any size,
// blocks that zip shrinks and blocks stored raw, NaN and infinities), reads
// the same layout uncompressed or one row a block as other writers store
// it, leaves every other layout (data layers, half floats, other
// compression, a data window off the origin) to OpenImageIO, and never
// takes a file cut short or a compressed block with a byte changed.

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "image/exr_rgb_reader.hpp"
#include "image/image_io.hpp"
#include "file_bytes.hpp"
#include "scratch_dir.hpp"

namespace lc {
namespace {

namespace fs = std::filesystem;

using test::bytes_of;
using test::put;

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// A w x h frame: a smooth ramp that zip shrinks, or (noise) random bit
// patterns it cannot, which OpenEXR then stores raw.
FrameImage frame(int w, int h, bool noise, bool with_alpha) {
  FrameImage im;
  im.width = w;
  im.height = h;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  im.rgb.resize(3 * n);
  std::mt19937 random(static_cast<unsigned>(w * 131 + h));
  for (std::size_t i = 0; i < im.rgb.size(); ++i) {
    if (noise) {
      std::uint32_t bits = random();
      std::memcpy(&im.rgb[i], &bits, sizeof bits);
    } else {
      im.rgb[i] = static_cast<float>(i % 97) * 0.01f - 0.2f;  // negative light too: out-of-gamut colour
    }
  }
  if (with_alpha) {
    im.alpha.resize(n);
    for (std::size_t p = 0; p < n; ++p) im.alpha[p] = static_cast<float>(p % 5) / 4.0f;
  }
  return im;
}

// Writes `im`'s RGB with OpenImageIO as `type` with `compression`, the way
// another program might store the same frame.
void write_with_oiio(const fs::path& path, const FrameImage& im, const char* compression,
                     OIIO::TypeDesc type = OIIO::TypeDesc::FLOAT, int x_origin = 0) {
  OIIO::ImageSpec spec(im.width, im.height, 3, type);
  spec.x = x_origin;
  spec.full_x = x_origin;
  spec.attribute("compression", compression);
  auto out = OIIO::ImageOutput::create("openexr");
  ASSERT_TRUE(out && out->open(path.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, im.rgb.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

TEST(ExrRgbReader, GivesBackBitForBitWhatWriteExrWrote) {
  test::ScratchDir dir;
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{7, 5}, std::pair{33, 17}, std::pair{64, 48}})
    for (const bool noise : {false, true})
      for (const bool alpha : {false, true}) {
        FrameImage im = frame(w, h, noise, alpha);
        if (!noise) {
          im.rgb[0] = std::numeric_limits<float>::quiet_NaN();
          im.rgb[im.rgb.size() - 1] = std::numeric_limits<float>::infinity();
        }
        const fs::path file = dir / "frame.exr";
        write_exr(file, im, {{"lightcone/shot", "a name long enough to matter"}});
        const std::optional<FrameImage> back = read_rgb_exr(file);
        ASSERT_TRUE(back) << w << "x" << h << " noise " << noise << " alpha " << alpha;
        EXPECT_EQ(back->width, w);
        EXPECT_EQ(back->height, h);
        EXPECT_TRUE(same_bits(back->rgb, im.rgb)) << w << "x" << h << " noise " << noise;
        EXPECT_TRUE(same_bits(back->alpha, im.alpha)) << w << "x" << h << " alpha " << alpha;
        EXPECT_TRUE(back->layers.empty());
        // read_exr takes this path: the same frame, whichever way it is read.
        EXPECT_TRUE(same_bits(read_exr(file).rgb, im.rgb));
      }
}

TEST(ExrRgbReader, ReadsTheLayoutUncompressedOrOneRowABlock) {
  test::ScratchDir dir;
  const FrameImage im = frame(19, 21, false, false);
  for (const char* compression : {"none", "zips", "zip"}) {
    const fs::path file = dir / (std::string(compression) + ".exr");
    write_with_oiio(file, im, compression);
    const std::optional<FrameImage> back = read_rgb_exr(file);
    ASSERT_TRUE(back) << compression;
    EXPECT_TRUE(same_bits(back->rgb, im.rgb)) << compression;
  }
}

TEST(ExrRgbReader, LeavesEveryOtherLayoutToOpenImageIo) {
  test::ScratchDir dir;
  const FrameImage im = frame(9, 6, false, false);
  const fs::path piz = dir / "piz.exr", half = dir / "half.exr", moved = dir / "moved.exr", layers = dir / "layers.exr";
  write_with_oiio(piz, im, "piz");
  write_with_oiio(half, im, "zip", OIIO::TypeDesc::HALF);
  write_with_oiio(moved, im, "zip", OIIO::TypeDesc::FLOAT, 3);
  FrameImage with_layers = im;
  with_layers.layers.push_back({"hit.r", std::vector<float>(9 * 6, 2.5f)});
  write_exr(layers, with_layers);
  for (const fs::path& file : {piz, half, moved, layers}) EXPECT_FALSE(read_rgb_exr(file)) << file;
  // read_exr still reads them all, through OpenImageIO.
  EXPECT_TRUE(same_bits(read_exr(piz).rgb, im.rgb));
  EXPECT_EQ(read_exr(layers).layers.size(), 1u);
  EXPECT_FALSE(read_rgb_exr(dir / "missing.exr"));
  write_png(dir / "frame.png", im);
  EXPECT_FALSE(read_rgb_exr(dir / "frame.png"));
}

TEST(ExrRgbReader, TakesNoFileCutShortAndNoChangedCompressedByte) {
  test::ScratchDir dir;
  const fs::path good = dir / "good.exr", bad = dir / "bad.exr";
  write_exr(good, frame(21, 35, false, true));  // three zip blocks, the last one short
  const std::string bytes = bytes_of(good);
  ASSERT_TRUE(read_rgb_exr(good));
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    put(bad, bytes.substr(0, n));
    EXPECT_FALSE(read_rgb_exr(bad)) << "cut at " << n << " of " << bytes.size();
  }
  // Every byte past the header and offset table belongs to a block: its row,
  // its size, or deflate's stream with its checksum.  Flipping one of them
  // must never give a frame (it may still give nullopt for another reason).
  const std::size_t table_end = bytes.size() - 1;  // scanned from the end: the blocks are the file's tail
  std::size_t refused = 0, tried = 0;
  for (std::size_t at = table_end; at > bytes.size() / 2; --at) {
    std::string changed = bytes;
    changed[at] = static_cast<char>(changed[at] ^ 0x5a);
    put(bad, changed);
    ++tried;
    refused += !read_rgb_exr(bad);
  }
  EXPECT_EQ(refused, tried);
}

}  // namespace
}  // namespace lc
