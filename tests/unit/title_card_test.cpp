// Title cards (video/title_card.hpp, video/pixel_font.hpp): the 5x7 font
// covers what titles and labels need, and cards scale and break their text
// to fit.

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

TEST(TitleCard, FontCoversTitlesAndFrameNumbers) {
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

TEST(TitleCard, TitleCardScalesTextToFit) {
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
TEST(TitleCard, TitleCardBreaksLinesToFitASmallDome) {
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

}  // namespace
