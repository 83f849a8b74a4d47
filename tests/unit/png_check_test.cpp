// The written PNG's structural check (image/png_check.hpp): a PNG as
// write_png makes it passes; one cut short anywhere, with a byte changed,
// with bytes after its end, of another size or not a PNG at all is refused
// saying why.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "image/image_io.hpp"
#include "image/png_check.hpp"
#include "file_bytes.hpp"
#include "scratch_dir.hpp"
#include "tiny_frame.hpp"

namespace lc {
namespace {

namespace fs = std::filesystem;

using test::bytes_of;
using test::put;

// The reason check_png_file gives, or "" when it passes.
std::string refusal(const fs::path& p, int w, int h) {
  try {
    check_png_file(p, w, h);
    return "";
  } catch (const std::runtime_error& e) {
    return e.what();
  }
}

TEST(PngCheck, AWrittenPngPassesAndADamagedOneIsRefused) {
  test::ScratchDir dir;
  const FrameImage frame = test::tiny_frame();
  const fs::path png = dir / "f.png";
  write_png(png, frame);
  EXPECT_EQ(refusal(png, frame.width, frame.height), "");
  EXPECT_NE(refusal(png, frame.width + 1, frame.height).find("not "), std::string::npos);
  const std::string good = bytes_of(png);

  // Cut short at every length: each is refused.
  for (std::size_t n = 0; n < good.size(); ++n) {
    put(dir / "cut.png", good.substr(0, n));
    EXPECT_NE(refusal(dir / "cut.png", frame.width, frame.height), "") << "cut to " << n << " bytes";
  }
  // One byte changed anywhere past the signature: a chunk's CRC (or its
  // frame) no longer holds.
  for (std::size_t i = 8; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] = static_cast<char>(bad[i] ^ 0x10);
    put(dir / "bad.png", bad);
    EXPECT_NE(refusal(dir / "bad.png", frame.width, frame.height), "") << "byte " << i << " changed";
  }
  put(dir / "tail.png", good + "x");
  EXPECT_EQ(refusal(dir / "tail.png", frame.width, frame.height), "1 bytes follow its IEND");
  put(dir / "text.png", "not a picture");
  EXPECT_EQ(refusal(dir / "text.png", frame.width, frame.height), "not a PNG (no PNG signature)");
  EXPECT_EQ(refusal(dir / "none.png", frame.width, frame.height), "cannot be opened");
}

}  // namespace
}  // namespace lc
