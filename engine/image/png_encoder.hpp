// The 8-bit PNG of a frame, made here rather than by OpenImageIO's writer:
// the same bytes libpng 1.6 writes through OpenImageIO 2.4 for the same
// pixels (the same chunks, each row's filter chosen by libpng's rule, zlib
// at libpng's settings, IDAT chunks of libpng's size), so every frame's PNG
// is what it was, but its filters are chosen in a fraction of the time
// libpng takes, a large share of writing a frame (docs/performance.md).
// tests/unit/png_encoder_test.cpp holds it to the PNG rules and to the
// pixels libpng decodes from it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace lc {

// Input: width x height pixels of 8-bit sRGB codes, R G B interleaved,
// rows top to bottom (3 * width * height bytes, width and height > 0).
// Output: the whole PNG file's bytes, tagged sRGB as OpenImageIO tags an
// sRGB image (gAMA, sRGB, cHRM, oFFs and its colour-space tEXt chunk).
// Throws std::invalid_argument for a size that does not match.
std::vector<unsigned char> encode_png8(std::span<const std::uint8_t> rgb, int width, int height);

}  // namespace lc
