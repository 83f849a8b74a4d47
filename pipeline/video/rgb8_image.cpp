#include "video/rgb8_image.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>

#include "image/image_io.hpp"
#include "image/srgb.hpp"
#include "image/srgb8_encoder.hpp"

namespace lc {

Rgb8Image Rgb8Image::filled(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  // Inputs: a size (assumed non-negative) and a colour; output: that image.
  Rgb8Image image{width, height, {}};
  image.pixels.resize(3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  for (std::size_t i = 0; i < image.pixels.size(); i += 3) {
    image.pixels[i] = r;
    image.pixels[i + 1] = g;
    image.pixels[i + 2] = b;
  }
  return image;
}

Rgb8Image to_rgb8(const FrameImage& image) {
  // Input: linear RGB; output: the sRGB codes (image/srgb8_encoder.hpp: exact).
  const Srgb8Encoder& encode = Srgb8Encoder::shared();
  Rgb8Image out{image.width, image.height, std::vector<std::uint8_t>(image.rgb.size())};
  std::transform(image.rgb.begin(), image.rgb.end(), out.pixels.begin(), std::cref(encode));
  return out;
}

FrameImage to_linear(const Rgb8Image& image) {
  // Input: sRGB codes; output: linear RGB, through a 256-entry table.
  std::array<float, 256> table{};
  for (int k = 0; k < 256; ++k) table[static_cast<std::size_t>(k)] = srgb8_to_linear(static_cast<std::uint8_t>(k));
  FrameImage out;
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(image.pixels.size());
  std::transform(image.pixels.begin(), image.pixels.end(), out.rgb.begin(), [&](std::uint8_t c) { return table[c]; });
  return out;
}

Rgb8Image read_rgb8(const std::filesystem::path& path) {
  // The image layer owns file formats (OIIO stays in engine/image); it hands
  // back linear float, which the table inverts without loss for 8-bit input.
  return to_rgb8(read_image_linear(path));
}

Rgb8Image pad_to_even(const Rgb8Image& image) {
  // Input: any image; output: even-sided copy, edges repeated (a repeated
  // edge is invisible where a black line would not be).
  const int w = image.width + image.width % 2, h = image.height + image.height % 2;
  if (w == image.width && h == image.height) return image;
  Rgb8Image out{w, h, std::vector<std::uint8_t>(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h))};
  for (int y = 0; y < h; ++y) {
    const int sy = std::min(y, image.height - 1);
    for (int x = 0; x < w; ++x) {
      const int sx = std::min(x, image.width - 1);
      const std::size_t d = 3 * (static_cast<std::size_t>(y) * w + x);
      const std::size_t s = 3 * (static_cast<std::size_t>(sy) * image.width + sx);
      std::copy_n(&image.pixels[s], 3, &out.pixels[d]);
    }
  }
  return out;
}

}  // namespace lc
