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

}  // namespace

Rgb8Image title_card(int width, int height, const std::vector<std::string>& lines, CardShape shape) {
  // Inputs: card size, text lines and where the text goes; output: the card.
  if (lines.empty()) throw std::invalid_argument("title card: no text");
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument(fmt::format("title card: size {}x{} out of range", width, height));
  const TextBox box = text_box(width, height, shape);
  namespace pf = pixel_font;
  // Line i > 0 is drawn at half the title's scale (at least 1): find the
  // largest title scale s for which everything fits.
  auto sub = [](int s) { return std::max(1, s / 2); };
  // Space above line i: two title pixels under the title, two subtitle
  // pixels between subtitles.
  auto gap = [&](std::size_t i, int s) { return i == 0 ? 0 : i == 1 ? 2 * s : 2 * sub(s); };
  auto block_height = [&](int s) {
    int block = 0;
    for (std::size_t i = 0; i < lines.size(); ++i) block += gap(i, s) + pf::text_height(i == 0 ? s : sub(s));
    return block;
  };
  auto fits = [&](int s) {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (pf::text_width(lines[i], i == 0 ? s : sub(s)) * 10 > box.width * 8) return false;
    return block_height(s) * 10 <= box.height * 7;
  };
  if (!fits(1))
    throw std::invalid_argument(
        fmt::format("title card: the text does not fit in {}x{} even at the smallest size (shorten the lines)", width,
                    height));
  int s = 1;
  while (fits(s + 1)) ++s;

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
  int y = box.y0 + (box.height - block_height(s)) / 2;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const int si = i == 0 ? s : sub(s);
    y += gap(i, s);
    const int x = box.x0 + (box.width - pf::text_width(lines[i], si)) / 2;
    pf::for_each_pixel(lines[i], si, [&](int px, int py) {
      const std::size_t k = 3 * (static_cast<std::size_t>(y + py) * width + static_cast<std::size_t>(x + px));
      std::copy_n(ink, 3, &card.pixels[k]);
    });
    y += pf::text_height(si);
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
