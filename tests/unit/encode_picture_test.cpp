// Tests of the encode stage's pictures: the 8-bit sRGB conversion is exact
// (a PNG's bytes come back unchanged), odd sizes pad by repeating the edge,
// the 5x7 font covers what titles and labels need, title cards scale their
// text to fit, the contact sheet's picks spread evenly, and its thumbnails,
// read a band of rows at a time, are the whole image's area average.

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

TEST(encode_picture, Srgb8RoundTripIsExact) {
  // Every code decoded to linear (what reading a PNG gives) encodes back to itself.
  lc::Rgb8Image img = lc::Rgb8Image::filled(256, 1, 0, 0, 0);
  for (int k = 0; k < 256; ++k)
    for (int c = 0; c < 3; ++c) img.pixels[static_cast<std::size_t>(3 * k + c)] = static_cast<std::uint8_t>(k);
  EXPECT_EQ(lc::to_rgb8(lc::to_linear(img)).pixels, img.pixels);
}

TEST(encode_picture, Srgb8MatchesTheFrameStoreCurve) {
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

TEST(encode_picture, OddSizesPadByRepeatingTheEdge) {
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

TEST(encode_picture, FontCoversTitlesAndFrameNumbers) {
  for (char c : std::string("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 .,:;-+=/()'!?%abcxyz"))
    EXPECT_TRUE(lc::pixel_font::has_glyph(c)) << "no glyph for '" << c << "'";
  EXPECT_FALSE(lc::pixel_font::has_glyph('\x01'));
  EXPECT_EQ(lc::pixel_font::text_width("", 3), 0);
  EXPECT_EQ(lc::pixel_font::text_width("12", 1), 11);
  EXPECT_EQ(lc::pixel_font::text_width("12", 3), 33);
  // Every glyph stays in its cell, and the digits differ from one another.
  std::set<std::string> shapes;
  for (char c : std::string("0123456789")) {
    std::string bits(35, '.');
    lc::pixel_font::for_each_pixel(std::string(1, c), 1, [&](int x, int y) {
      ASSERT_TRUE(x >= 0 && x < 5 && y >= 0 && y < 7) << c;
      bits[static_cast<std::size_t>(y * 5 + x)] = '#';
    });
    shapes.insert(bits);
  }
  EXPECT_EQ(shapes.size(), 10u);
  // At scale 2 each font pixel is a 2x2 block.
  int lit1 = 0, lit2 = 0;
  lc::pixel_font::for_each_pixel("M", 1, [&](int, int) { ++lit1; });
  lc::pixel_font::for_each_pixel("M", 2, [&](int, int) { ++lit2; });
  EXPECT_EQ(lit2, 4 * lit1);
}

TEST(encode_picture, TitleCardScalesTextToFit) {
  const lc::Rgb8Image card = lc::title_card(640, 360, {"KERR", "accretion disk"});
  ASSERT_EQ(card.width, 640);
  ASSERT_EQ(card.height, 360);
  // The ink's bounding box is centred and within 80% of the width.
  int x0 = 640, x1 = -1, y0 = 360, y1 = -1;
  for (int y = 0; y < 360; ++y)
    for (int x = 0; x < 640; ++x)
      if (card.pixels[3 * (static_cast<std::size_t>(y) * 640 + static_cast<std::size_t>(x))] > 128) {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
        y1 = std::max(y1, y);
      }
  ASSERT_GE(x1, 0) << "no text drawn";
  EXPECT_LE(x1 - x0 + 1, 512);
  EXPECT_GE(x1 - x0 + 1, 400) << "text should be large";
  EXPECT_NEAR((x0 + x1) / 2.0, 320, 4);
  EXPECT_NEAR((y0 + y1) / 2.0, 180, 8);
  EXPECT_THROW(lc::title_card(64, 36, {"FAR TOO LONG FOR THIS CARD"}), std::invalid_argument);
  EXPECT_THROW(lc::title_card(64, 36, {}), std::invalid_argument);
}

// The paper's titles on a small dome master (192 and 256 pixels, the
// preview's): a title wider than the dome's text box is broken between words
// instead of leaving the card blank, and every lit pixel lies inside the disc.
TEST(encode_picture, TitleCardBreaksLinesToFitASmallDome) {
  for (const int side : {192, 256})
    for (const char* title : {"A SPINNING BLACK HOLE", "FALLING PAST IT", "TWO CHARGED BLACK HOLES", "LIGHTCONE"}) {
      lc::Rgb8Image card;
      ASSERT_NO_THROW(card = lc::title_card(side, side, {title}, lc::CardShape::dome)) << side << " " << title;
      int lit = 0, rows_with_ink = 0;
      for (int y = 0; y < side; ++y) {
        bool row_lit = false;
        for (int x = 0; x < side; ++x)
          if (card.pixels[3 * (static_cast<std::size_t>(y) * side + static_cast<std::size_t>(x))] > 128) {
            ++lit;
            row_lit = true;
            const double dx = x + 0.5 - 0.5 * side, dy = y + 0.5 - 0.5 * side;
            EXPECT_LE(dx * dx + dy * dy, 0.25 * side * side) << side << " " << title << " at " << x << "," << y;
          }
        rows_with_ink += row_lit;
      }
      EXPECT_GT(lit, 0) << side << " " << title << ": a blank card";
      // Two words or more that did not fit one line take two lines (14 rows of ink at least).
      if (std::string_view(title).size() > 16) EXPECT_GE(rows_with_ink, 14) << side << " " << title;
    }
  // A single word wider than the box still cannot be drawn.
  EXPECT_THROW(lc::title_card(64, 64, {"UNBREAKABLEWORD"}, lc::CardShape::dome), std::invalid_argument);
}

TEST(contact_sheet, PicksSpreadEvenlyWithFirstAndLast) {
  EXPECT_EQ(lc::pick_evenly(5, 16), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(lc::pick_evenly(900, 4), (std::vector<std::size_t>{0, 300, 599, 899}));
  EXPECT_EQ(lc::pick_evenly(10, 1), (std::vector<std::size_t>{0}));
  EXPECT_TRUE(lc::pick_evenly(0, 4).empty());
  for (std::size_t n = 2; n < 60; ++n)
    for (std::size_t k = 2; k < n; ++k) {
      const auto p = lc::pick_evenly(n, k);
      ASSERT_EQ(p.size(), k);
      EXPECT_EQ(p.front(), 0u);
      EXPECT_EQ(p.back(), n - 1);
      for (std::size_t i = 1; i < k; ++i) ASSERT_LT(p[i - 1], p[i]) << n << " " << k;
    }
}

// The area average as the contact sheet made it before it read frames in
// bands (the whole image in memory, both axes' weights at once): what the
// band-by-band thumbnail must equal.
lc::FrameImage whole_image_average(const lc::FrameImage& src, int w, int h) {
  auto spans = [](int n_src, int n_dst) {
    std::vector<std::pair<int, std::vector<double>>> s(static_cast<std::size_t>(n_dst));
    const double ratio = static_cast<double>(n_src) / n_dst;
    for (int d = 0; d < n_dst; ++d) {
      const double a = d * ratio, b = (d + 1) * ratio;
      const int first = static_cast<int>(std::floor(a));
      const int last = std::min(n_src - 1, static_cast<int>(std::ceil(b)) - 1);
      s[static_cast<std::size_t>(d)].first = first;
      for (int k = first; k <= last; ++k)
        s[static_cast<std::size_t>(d)].second.push_back((std::min<double>(b, k + 1) - std::max<double>(a, k)) / ratio);
    }
    return s;
  };
  const auto xs = spans(src.width, w), ys = spans(src.height, h);
  lc::FrameImage out;
  out.width = w;
  out.height = h;
  out.rgb.assign(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto& [fy, wy] = ys[static_cast<std::size_t>(y)];
      const auto& [fx, wx] = xs[static_cast<std::size_t>(x)];
      double acc[3] = {0, 0, 0};
      for (std::size_t j = 0; j < wy.size(); ++j)
        for (std::size_t i = 0; i < wx.size(); ++i)
          for (std::size_t c = 0; c < 3; ++c)
            acc[c] += wy[j] * wx[i] *
                      src.rgb[3 * ((static_cast<std::size_t>(fy) + j) * static_cast<std::size_t>(src.width) +
                                   static_cast<std::size_t>(fx) + i) +
                              c];
      for (std::size_t c = 0; c < 3; ++c)
        out.rgb[3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) + c] =
            static_cast<float>(acc[c]);
    }
  return out;
}

TEST(contact_sheet, ABandByBandThumbnailIsTheWholeImagesAreaAverage) {
  lc::test::ScratchDir dir;
  std::mt19937 rng(25);
  // 1000 x 700: many bands of 64 rows and a short last one; then a small
  // frame blown up (each output row then takes a part of one source row).
  for (const auto [w, h, tw, th] : {std::array{1000, 700, 154, 108}, std::array{32, 18, 160, 90}}) {
    lc::FrameImage frame;
    frame.width = w;
    frame.height = h;
    frame.rgb.resize(3 * static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (float& v : frame.rgb) v = std::uniform_real_distribution<float>(0.0f, 1.0f)(rng);
    const auto file = dir / "frame.png";
    lc::write_png(file, frame);
    const lc::FrameImage expected = whole_image_average(lc::read_image_linear(file), tw, th);
    const lc::FrameImage got = lc::thumbnail(file, tw, th, {w, h});
    ASSERT_EQ(got.width, tw);
    ASSERT_EQ(got.height, th);
    ASSERT_EQ(got.rgb.size(), expected.rgb.size());
    for (std::size_t i = 0; i < got.rgb.size(); ++i)
      ASSERT_NEAR(got.rgb[i], expected.rgb[i], 1e-6f * std::max(1.0f, expected.rgb[i])) << i;
    // A frame of another size than the sequence's first is named.
    EXPECT_THROW(lc::thumbnail(file, tw, th, {w + 1, h}), std::runtime_error);
  }
}

}  // namespace
