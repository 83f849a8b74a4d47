#pragma once
// The encode stage's picture: 8-bit sRGB RGB, row-major, row 0 at the top —
// what a frame's PNG holds and what the video encoder is fed.  Kept apart
// from the engine's FrameImage (linear float) so title cards and padding work
// on the bytes that end up in the video.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "image/frame_image.hpp"

namespace lc {

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  // 3 * width * height, R G B

  // A width x height image filled with one colour.
  static Rgb8Image filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b);
};

// Linear float RGB -> 8-bit sRGB codes, the curve write_png applies (so a
// PNG read back and converted gives its own bytes again).  Layers are ignored.
Rgb8Image to_rgb8(const FrameImage& image);

// 8-bit sRGB -> linear float RGB (for write_png and for resampling in linear light).
FrameImage to_linear(const Rgb8Image& image);

// Reads any image the image layer reads (a frame's PNG) as 8-bit sRGB.
// Throws std::runtime_error naming the file.
Rgb8Image read_rgb8(const std::filesystem::path& path);

// The image grown to even width and height by repeating its last column
// and/or row (yuv420p stores colour per 2x2 block, so encoders need even
// sides); unchanged when both are even.
Rgb8Image pad_to_even(const Rgb8Image& image);

}  // namespace lc
