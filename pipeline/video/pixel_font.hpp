#pragma once
// A tiny built-in 5x7 pixel font (capitals, digits, common punctuation) for
// title cards and contact-sheet labels, so the encode stage needs no font
// library.  Lower-case letters are drawn as capitals; a character without a
// glyph is drawn as a hollow box, so it shows instead of vanishing.

#include <functional>
#include <string_view>

namespace lc::pixel_font {

inline constexpr int glyph_width = 5;
inline constexpr int glyph_height = 7;
inline constexpr int advance = 6;  // glyph plus one column of space

// True when `c` has its own glyph (after mapping lower case to upper).
bool has_glyph(char c);

// Size of `text` on one line at `scale` (each font pixel a scale x scale
// block): (6 n - 1) scale wide, 7 scale high; 0 wide for empty text.
int text_width(std::string_view text, int scale);
inline int text_height(int scale) { return glyph_height * scale; }

// Calls plot(x, y) for every image pixel `text` covers, drawn at `scale`
// with its top-left corner at (0, 0); the caller offsets and clips.
void for_each_pixel(std::string_view text, int scale, const std::function<void(int x, int y)>& plot);

}  // namespace lc::pixel_font
