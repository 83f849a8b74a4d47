#include "video/title_card.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "video/pixel_font.hpp"

namespace lc {

namespace {
// Colours (sRGB codes): a background a touch lifted from black so the
// card's edge shows against a player's black, text not quite white.
constexpr std::uint8_t background[3] = {12, 12, 16};
constexpr std::uint8_t ink[3] = {230, 230, 230};


// The rectangle the text is fitted and centred in.
struct TextBox {
  int x0, y0, width, height;
};

TextBox text_box(int width, int height, CardShape shape) {
  if (shape == CardShape::flat) return {0, 0, width, height};
  const double r = 0.5 * std::min(width, height), cx = 0.5 * width, cy = 0.5 * height + 0.61 * r;
  const int w = static_cast<int>(r), h = static_cast<int>(0.5 * r);
  return {static_cast<int>(cx) - w / 2, static_cast<int>(cy) - h / 2, w, h};
}

// One drawn line: its text, its scale and the space above it.
struct DrawnLine {
  std::string text;
  int scale, gap;
};

// The card's words broken into lines of at most `max_width` image pixels at
// `scale`, greedily; empty when a single word is wider than that.
std::vector<std::string> wrap_words(const std::string& line, int scale, int max_width) {
  std::vector<std::string> out;
  std::string current;
  std::size_t k = 0;
  while (k < line.size()) {
    const std::size_t space = line.find(' ', k);
    const std::string word = line.substr(k, space == std::string::npos ? std::string::npos : space - k);
    k = space == std::string::npos ? line.size() : space + 1;
    if (word.empty()) continue;
    if (pixel_font::text_width(word, scale) > max_width) return {};
    const std::string joined = current.empty() ? word : current + " " + word;
    if (pixel_font::text_width(joined, scale) <= max_width) {
      current = joined;
    } else {
      out.push_back(current);
      current = word;
    }
  }
  if (!current.empty()) out.push_back(current);
  return out;
}

// The lines as drawn at title scale s in `box`, with the title at s and the
// subtitles at half of it (at least 1); with `wrap`, a line too wide for the
// box is broken between words, each part at its line's scale.  Empty when
// they do not fit: every line within 80% of the box's width and the block
// within 70% of its height.
std::vector<DrawnLine> fit_lines(const std::vector<std::string>& lines, int s, const TextBox& box, bool wrap) {
  namespace pf = pixel_font;
  const int sub = std::max(1, s / 2);
  std::vector<DrawnLine> drawn;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int si = i == 0 ? s : sub;
    // Two title pixels under the title, two subtitle pixels between the
    // others; a wrapped line's parts two of its own pixels apart.
    const int gap = i == 0 ? 0 : i == 1 ? 2 * s : 2 * sub;
    std::vector<std::string> parts{lines[i]};
    if (wrap && pf::text_width(lines[i], si) * 10 > box.width * 8) {
      parts = wrap_words(lines[i], si, box.width * 8 / 10);
      if (parts.empty()) return {};
    }
    for (std::size_t p = 0; p < parts.size(); ++p) {
      if (pf::text_width(parts[p], si) * 10 > box.width * 8) return {};
      drawn.push_back({parts[p], si, p == 0 ? gap : 2 * si});
    }
  }
  int block = 0;
  for (const DrawnLine& d : drawn) block += d.gap + pf::text_height(d.scale);
  if (block * 10 > box.height * 7) return {};
  return drawn;
}

}  // namespace

Rgb8Image title_card(int width, int height, const std::vector<std::string>& lines, CardShape shape) {
  // Inputs: card size, text lines and where the text goes; output: the card.
  if (lines.empty()) throw std::invalid_argument("title card: no text");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument(fmt::format("title card: size {}x{} out of range", width, height));
  const TextBox box = text_box(width, height, shape);
  namespace pf = pixel_font;
  // The largest title scale at which the lines fit as written; only a card
  // too small for that breaks its lines between words (so every card that
  // fitted before is drawn as before).
  std::vector<DrawnLine> drawn;
  for (const bool wrap : {false, true}) {
    for (int s = 1;; ++s) {
      std::vector<DrawnLine> at_s = fit_lines(lines, s, box, wrap);
      if (at_s.empty()) break;
      drawn = std::move(at_s);
    }
    if (!drawn.empty()) break;
  }
  if (drawn.empty())
    throw std::invalid_argument(
        fmt::format("title card: the text does not fit in {}x{} even at the smallest size (shorten the lines)", width,
                    height));

  Rgb8Image card = Rgb8Image::filled(width, height, background[0], background[1], background[2]);
  if (shape == CardShape::dome) {
    // Black outside the disc, as a dome master's frames are.
    const double r = 0.5 * std::min(width, height);
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        const double x = i + 0.5 - 0.5 * width, y = j + 0.5 - 0.5 * height;
        if (x * x + y * y > r * r) std::fill_n(&card.pixels[3 * (static_cast<std::size_t>(j) * width + i)], 3, 0);
      }
  }
  int block = 0;
  for (const DrawnLine& d : drawn) block += d.gap + pf::text_height(d.scale);
  int y = box.y0 + (box.height - block) / 2;
  for (const DrawnLine& d : drawn) {
    y += d.gap;
    const int x = box.x0 + (box.width - pf::text_width(d.text, d.scale)) / 2;
    pf::for_each_pixel(d.text, d.scale, [&](int px, int py) {
      const std::size_t k = 3 * (static_cast<std::size_t>(y + py) * width + static_cast<std::size_t>(x + px));
      std::copy_n(ink, 3, &card.pixels[k]);
    });
    y += pf::text_height(d.scale);
  }
  return card;
}

EncodeResult encode_title_card(const std::vector<std::string>& lines, int width, int height, int frames,
                               const EncodeOptions& options, const std::filesystem::path& out,
                               const ProgressFn& progress, CardShape shape) {
  // Inputs: text, size, length in frames, options; output: the clip at `out`.
  return encode_still(title_card(width, height, lines, shape), frames, options, out, progress);
}

}  // namespace lc
