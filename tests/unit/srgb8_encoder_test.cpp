// The table-driven sRGB encoder (image/srgb8_encoder.hpp) gives
// linear_to_srgb8's code for every float: checked here on every 13th float
// in (0, 1) and on the 512 floats around each code boundary (all 1.07e9
// floats in (0, 1) were checked once: docs/performance.md, change 45).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "image/srgb8_encoder.hpp"

namespace lc {
namespace {

float from_bits(std::uint32_t bits) {
  float c;
  std::memcpy(&c, &bits, sizeof c);
  return c;
}

TEST(Srgb8Encoder, GivesTheCurvesCodeForEveryFloat) {
  const Srgb8Encoder& encode = Srgb8Encoder::shared();
  long mismatches = 0;
  for (std::uint32_t bits = 1; from_bits(bits) < 1.0f; bits += 13)
    if (encode(from_bits(bits)) != linear_to_srgb8(from_bits(bits)) && ++mismatches < 5)
      ADD_FAILURE() << std::hexfloat << from_bits(bits);
  for (int k = 0; k < 255; ++k) {
    float c = static_cast<float>(srgb_to_linear((k + 0.5) / 255.0));
    for (int i = 0; i < 256; ++i) c = std::nextafter(c, 0.0f);
    for (int i = 0; i < 512; ++i, c = std::nextafter(c, 2.0f))
      if (encode(c) != linear_to_srgb8(c) && ++mismatches < 5) ADD_FAILURE() << std::hexfloat << c;
  }
  EXPECT_EQ(mismatches, 0);
  for (float c : {0.0f, -0.0f, -1.0f, std::nanf(""), 1.0f, 1e30f, std::numeric_limits<float>::denorm_min()})
    EXPECT_EQ(encode(c), linear_to_srgb8(c)) << c;
}

}  // namespace
}  // namespace lc
