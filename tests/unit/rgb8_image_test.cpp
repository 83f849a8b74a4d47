// The encode stage's 8-bit pictures (video/rgb8_image.hpp): the sRGB
// conversion is exact (a PNG's bytes come back unchanged) and odd sizes pad
// by repeating the edge.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>

#include "image/image_io.hpp"
#include "image/srgb.hpp"
#include "scratch_dir.hpp"
#include "video/contact_sheet.hpp"
#include "video/pixel_font.hpp"
#include "video/rgb8_image.hpp"
#include "video/title_card.hpp"

namespace {

TEST(Rgb8Image, Srgb8RoundTripIsExact) {
  // Every code decoded to linear (what reading a PNG gives) encodes back to itself.
  lc::Rgb8Image img = lc::Rgb8Image::filled(256, 1, 0, 0, 0);
  for (int k = 0; k < 256; ++k)
    for (int c = 0; c < 3; ++c) img.pixels[static_cast<std::size_t>(3 * k + c)] = static_cast<std::uint8_t>(k);
  EXPECT_EQ(lc::to_rgb8(lc::to_linear(img)).pixels, img.pixels);
}

TEST(Rgb8Image, Srgb8MatchesTheFrameStoreCurve) {
  // The table-driven encoder agrees with linear_to_srgb8 (what write_png
  // uses) on random values, at every rounding boundary (and a hair on each
  // side), and at the edges: negative, NaN, 1 and above.
  lc::FrameImage f;
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-0.1f, 1.1f);
  for (int i = 0; i < 200000; ++i) f.rgb.push_back(u(rng));
  for (int k = 0; k < 255; ++k) {
    const float b = static_cast<float>(lc::srgb_to_linear((k + 0.5) / 255.0));
    f.rgb.insert(f.rgb.end(), {std::nextafter(b, 0.0f), b, std::nextafter(b, 2.0f)});
  }
  f.rgb.insert(f.rgb.end(), {0.0f, -1.0f, std::nanf(""), 1.0f, 7.0f, 1e-30f});
  while (f.rgb.size() % 3) f.rgb.push_back(0.5f);
  f.width = static_cast<int>(f.rgb.size() / 3);
  f.height = 1;
  const lc::Rgb8Image r = lc::to_rgb8(f);
  int mismatches = 0;
  for (std::size_t i = 0; i < f.rgb.size(); ++i)
    if (r.pixels[i] != lc::linear_to_srgb8(f.rgb[i]) && ++mismatches < 5)
      ADD_FAILURE() << "value " << f.rgb[i] << ": " << int(r.pixels[i]) << " vs " << int(lc::linear_to_srgb8(f.rgb[i]));
  EXPECT_EQ(mismatches, 0);
}

TEST(Rgb8Image, OddSizesPadByRepeatingTheEdge) {
  lc::Rgb8Image img = lc::Rgb8Image::filled(3, 1, 10, 20, 30);
  img.pixels[6] = 200;  // the last pixel's red
  const lc::Rgb8Image p = lc::pad_to_even(img);
  ASSERT_EQ(p.width, 4);
  ASSERT_EQ(p.height, 2);
  EXPECT_EQ(p.pixels[3 * 3], 200);          // column 3 repeats column 2
  EXPECT_EQ(p.pixels[3 * (4 + 3)], 200);    // row 1 repeats row 0
  EXPECT_EQ(p.pixels[3 * 4 + 1], 20);
  const lc::Rgb8Image even = lc::Rgb8Image::filled(4, 2, 1, 2, 3);
  EXPECT_EQ(lc::pad_to_even(even).pixels, even.pixels);
}

}  // namespace
