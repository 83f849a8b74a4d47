#pragma once
// Linear float -> 8-bit sRGB code exactly as linear_to_srgb8 (image/srgb.hpp)
// rounds, but without a pow() per channel (a 720p frame has 2.8 million):
// what the frame writer's PNG and the encoder's pictures use.  Code k+1
// begins where the curve crosses k + 0.5.  Those 255 boundaries are at
// least 3e-4 apart (the curve's steepest part, near black), so a table over
// [0, 1) in steps of 1/8192 has at most one boundary per bucket: the
// bucket's first code plus one comparison gives the answer.  Exact on every
// float because linear_to_srgb8 is non-decreasing in its argument (a pow
// error of a fraction of a double's ulp cannot undo a float step, ~1e8 of
// them), and each boundary is the smallest float it sends to k+1.

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "image/srgb.hpp"

namespace lc {

class Srgb8Encoder {
 public:
  Srgb8Encoder() {
    for (int k = 0; k < 255; ++k) {
      // The curve's crossing, rounded to float, then nudged to the smallest
      // float linear_to_srgb8 sends to k+1: the two then agree on every float.
      float b = static_cast<float>(srgb_to_linear((k + 0.5) / 255.0));
      while (linear_to_srgb8(b) > k) b = std::nextafter(b, 0.0f);
      while (linear_to_srgb8(b) <= k) b = std::nextafter(b, 2.0f);
      upper_[static_cast<std::size_t>(k)] = b;
    }
    upper_[255] = 2.0f;  // above every value that reaches the lookup
    int code = 0;
    for (int b = 0; b < buckets; ++b) {
      const float lo = static_cast<float>(b) / buckets;
      while (code < 255 && upper_[static_cast<std::size_t>(code)] <= lo) ++code;
      first_[static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(code);
    }
  }

  std::uint8_t operator()(float c) const {
    if (!(c > 0.0f)) return 0;  // also NaN, like linear_to_srgb8
    if (c >= 1.0f) return 255;
    const std::uint8_t k = first_[static_cast<std::size_t>(c * buckets)];
    return static_cast<std::uint8_t>(k + (c >= upper_[k] ? 1 : 0));
  }

  // The one table, built on first use (a constant: thread-safe to share).
  static const Srgb8Encoder& shared() {
    static const Srgb8Encoder encoder;
    return encoder;
  }

 private:
  static constexpr int buckets = 8192;
  std::array<float, 256> upper_{};             // upper_[k]: where code k+1 begins
  std::array<std::uint8_t, buckets> first_{};  // code at each bucket's lower edge
};

}  // namespace lc
