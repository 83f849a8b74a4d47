#pragma once
// An equirectangular sky texture held in memory as linear RGB floats, read
// once per shot and then sampled by every escaping ray.  Sampling is inline
// and touches only this object's own pixel vector (no OIIO, no allocation,
// no virtual call), so textures are safe to share between render threads.

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <utility>
#include <vector>

#include "image/frame_image.hpp"

namespace lc {

class Texture {
 public:
  // Reads any image OpenImageIO understands and converts it to linear RGB
  // (see read_image_linear: the colour-space tag decides, else integer data
  // is sRGB and floating point is linear; grey is replicated; alpha
  // composites over black).  Throws std::runtime_error naming the file for a
  // missing or unreadable file, a file that is not an image, a zero-size
  // image or one above max_image_side (frame_image.hpp) a side, or one of
  // more than max_pixels pixels (checked before any is read).
  static Texture load(const std::filesystem::path& path, long max_pixels = long{max_image_side} * max_image_side);

  // A texture from linear RGB pixels (3 floats a pixel, row 0 at the top),
  // for procedural skies and tests.  Throws std::invalid_argument when the
  // size is not positive (or above max_image_side) or rgb.size() != 3*w*h.
  static Texture from_pixels(int width, int height, std::vector<float> rgb);

  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t bytes() const { return rgb_.size() * sizeof(float); }

  // Bilinear lookup at texture coordinates (u, v): u is periodic (any real
  // value wraps into [0, 1), so phi / 2 pi needs no care at the seam), v is
  // clamped to [0, 1]; v = 0 is the top row (theta = 0).  Texel (i, j) has
  // its centre at ((i + 0.5) / width, (j + 0.5) / height).  Writes linear
  // RGB to rgb[0..2].  A non-finite u or v reads as 0.
  void sample(double u, double v, float rgb[3]) const {
    if (!std::isfinite(u)) u = 0.0;
    const double x = (u - std::floor(u)) * width_ - 0.5;  // in [-0.5, width - 0.5]
    double y = v * height_ - 0.5;
    if (!(y > 0.0)) y = 0.0;  // also catches NaN
    if (y > height_ - 1) y = height_ - 1;

    const double xf = std::floor(x);
    const int x0 = static_cast<int>(xf);  // in [-1, width - 1]
    const int i0 = x0 < 0 ? width_ - 1 : x0;
    const int i1 = x0 + 1 >= width_ ? 0 : x0 + 1;
    const int j0 = static_cast<int>(y);
    const int j1 = j0 + 1 < height_ ? j0 + 1 : j0;
    const float tx = static_cast<float>(x - xf);
    const float ty = static_cast<float>(y - j0);

    // Weights (1 - t), t rather than a + t (b - a): the midpoint of two
    // texels is then their exactly rounded mean.
    const float w00 = (1.0f - tx) * (1.0f - ty), w10 = tx * (1.0f - ty);
    const float w01 = (1.0f - tx) * ty, w11 = tx * ty;
    const std::size_t row0 = static_cast<std::size_t>(j0) * static_cast<std::size_t>(width_);
    const std::size_t row1 = static_cast<std::size_t>(j1) * static_cast<std::size_t>(width_);
    const float* p00 = &rgb_[3 * (row0 + static_cast<std::size_t>(i0))];
    const float* p10 = &rgb_[3 * (row0 + static_cast<std::size_t>(i1))];
    const float* p01 = &rgb_[3 * (row1 + static_cast<std::size_t>(i0))];
    const float* p11 = &rgb_[3 * (row1 + static_cast<std::size_t>(i1))];
    for (int c = 0; c < 3; ++c) rgb[c] = w00 * p00[c] + w10 * p10[c] + w01 * p01[c] + w11 * p11[c];
  }

 private:
  Texture(int width, int height, std::vector<float> rgb) : width_(width), height_(height), rgb_(std::move(rgb)) {}

  int width_ = 0, height_ = 0;
  std::vector<float> rgb_;  // 3 * width * height, linear
};

}  // namespace lc
