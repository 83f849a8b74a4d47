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

// The byte that ends an EXR's header (the empty name after its last attribute).
std::size_t header_end(const std::string& b) {
  std::size_t at = 8;
  while (b[at] != '\0') {
    const std::size_t type_end = b.find('\0', b.find('\0', at) + 1);
    std::int32_t size = 0;
    std::memcpy(&size, &b[type_end + 1], sizeof size);
    at = type_end + 5 + static_cast<std::size_t>(size);
  }
  return at;
}

// Where the value of attribute `name` starts.
std::size_t value_at(const std::string& b, const std::string& name) {
  const std::size_t at = b.find(std::string("\0", 1) + name + std::string("\0", 1));
  return b.find('\0', at + name.size() + 2) + 5;
}

// An attribute as the header stores it: name, type, declared size, value.
std::string attribute(const std::string& name, const std::string& type, const std::string& value,
                      std::int32_t declared) {
  std::string a = name + std::string("\0", 1) + type + std::string("\0", 1) + std::string(4, '\0') + value;
  std::memcpy(&a[name.size() + type.size() + 2], &declared, sizeof declared);
  return a;
}

// `b` with `extra` added at the end of its header, every block's offset
// moved past it (the file is otherwise whole).
std::string with_attribute(const std::string& b, const std::string& extra, int blocks) {
  const std::size_t end = header_end(b);
  std::string out = b.substr(0, end) + extra + b.substr(end);
  for (int i = 0; i < blocks; ++i) {
    std::uint64_t offset = 0;
    std::memcpy(&offset, &out[end + 1 + extra.size() + 8 * static_cast<std::size_t>(i)], sizeof offset);
    offset += extra.size();
    std::memcpy(&out[end + 1 + extra.size() + 8 * static_cast<std::size_t>(i)], &offset, sizeof offset);
  }
  return out;
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

TEST(ExrRgbReader, LeavesHeadersOpenExrReadsOtherwiseToOpenImageIo) {
  // Each file below is one OpenEXR would refuse or read differently from
  // this reader; it must say nullopt (and OpenImageIO then decides).  The
  // first one, a harmless attribute added the same way, shows the edits
  // themselves leave a file it reads.
  test::ScratchDir dir;
  const fs::path file = dir / "edited.exr";
  const FrameImage im = frame(6, 20, false, false);  // two zip blocks
  write_exr(dir / "good.exr", im);
  const std::string good = bytes_of(dir / "good.exr");
  const auto reads = [&](const std::string& bytes) {
    put(file, bytes);
    return read_rgb_exr(file).has_value();
  };
  ASSERT_TRUE(reads(with_attribute(good, attribute("note", "string", "hello", 5), 2)));

  const std::string bgr = good.substr(value_at(good, "channels"), 55);
  EXPECT_FALSE(reads(with_attribute(good, attribute("channels", "chlist", bgr, 55), 2))) << "channels twice";
  EXPECT_FALSE(reads(with_attribute(good, attribute("focus", "float", std::string(32, '\0'), 32), 2)))
      << "a float declared 32 bytes long";
  EXPECT_FALSE(reads(with_attribute(good, attribute(std::string(40, 'n'), "string", "x", 1), 2)))
      << "a long name without the long-names flag";
  EXPECT_FALSE(reads(with_attribute(good, attribute("thumb", "preview", std::string(8, '\0'), 8), 2)))
      << "a preview";

  std::string random_order = good;
  random_order[value_at(good, "lineOrder")] = 2;
  EXPECT_FALSE(reads(random_order)) << "lineOrder 2 (random)";
  std::string flat = good;
  std::memset(&flat[value_at(good, "pixelAspectRatio")], 0, 4);
  EXPECT_FALSE(reads(flat)) << "pixelAspectRatio 0";

  // Block 1 copied to the file's end and the table pointed there: OpenEXR
  // reads on from block 0 to where block 1 was, this reader would follow
  // the table.
  const std::size_t table = header_end(good) + 1;
  std::uint64_t second = 0;
  std::memcpy(&second, &good[table + 8], sizeof second);
  std::string moved = good + good.substr(second);
  const std::uint64_t at_end = good.size();
  std::memcpy(&moved[table + 8], &at_end, sizeof at_end);
  EXPECT_FALSE(reads(moved)) << "a block away from where the one before it ends";

  fs::create_directory(dir / "folder.exr");
  EXPECT_FALSE(read_rgb_exr(dir / "folder.exr")) << "a directory";
}

TEST(ExrRgbReader, ReadsBlocksStoredBottomFirst) {
  test::ScratchDir dir;
  const FrameImage im = frame(13, 37, false, false);
  const fs::path file = dir / "decreasing.exr";
  OIIO::ImageSpec spec(im.width, im.height, 3, OIIO::TypeDesc::FLOAT);
  spec.attribute("compression", "zip");
  spec.attribute("openexr:lineOrder", "decreasingY");
  auto out = OIIO::ImageOutput::create("openexr");
  ASSERT_TRUE(out && out->open(file.string(), spec)) << OIIO::geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, im.rgb.data()));
  ASSERT_TRUE(out->close());
  const std::optional<FrameImage> back = read_rgb_exr(file);
  ASSERT_TRUE(back);
  EXPECT_TRUE(same_bits(back->rgb, im.rgb));
}

}  // namespace
}  // namespace lc
