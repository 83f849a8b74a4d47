#include "image_size.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

namespace lc {

namespace {

// The whole of `digits` as a non-negative int; nullopt when it is not a run
// of decimal digits or (then `too_large` is set) does not fit an int.
std::optional<int> whole_number(std::string_view digits, bool& too_large) {
  too_large = false;
  if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  int v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec == std::errc::result_out_of_range) {
    too_large = true;
    return std::nullopt;
  }
  if (ec != std::errc() || end != digits.data() + digits.size()) return std::nullopt;
  return v;
}

// Two whole numbers around one of `separators`, or the error for `flag`
// ("expected ..." completes the message).
std::pair<int, int> parse_pair(const std::string& text, const char* separators, const std::string& flag,
                               const char* expected) {
  const std::size_t at = text.find_first_of(separators);
  const std::string_view all(text);
  const std::string_view a_text = at == std::string::npos ? all : all.substr(0, at);
  const std::string_view b_text = at == std::string::npos ? std::string_view() : all.substr(at + 1);
  bool a_large = false, b_large = false;
  const std::optional<int> a = whole_number(a_text, a_large), b = whole_number(b_text, b_large);
  if (a_large || b_large)
    throw std::invalid_argument(fmt::format("{} '{}': {} is far too large", flag, text, a_large ? a_text : b_text));
  if (!a || !b) throw std::invalid_argument(fmt::format("{} '{}': expected {}", flag, text, expected));
  return {*a, *b};
}

}  // namespace

std::pair<int, int> parse_image_size(const std::string& text, const std::string& flag) {
  return parse_pair(text, "xX", flag, "WxH, two whole numbers of pixels, e.g. 1280x720");
}

std::pair<int, int> parse_pixel(const std::string& text, const std::string& flag) {
  return parse_pair(text, ",", flag, "I,J (column from the left, row from the top, from 0)");
}

Region parse_region(const std::string& text, int frame_width, int frame_height) {
  const std::string flag = "--region";
  int v[4];
  std::size_t from = 0;
  for (int k = 0; k < 4; ++k) {
    const std::size_t comma = k < 3 ? text.find(',', from) : std::string::npos;
    const std::string_view part =
        comma == std::string::npos && k < 3 ? std::string_view() : std::string_view(text).substr(from, comma - from);
    bool too_large = false;
    const std::optional<int> n = whole_number(part, too_large);
    if (too_large) throw std::invalid_argument(fmt::format("{} '{}': {} is far too large", flag, text, part));
    if (!n || (k == 3 && text.find(',', from) != std::string::npos))
      throw std::invalid_argument(fmt::format("{} '{}': expected X0,Y0,X1,Y1, four whole numbers of pixels (X1 and Y1 "
                                              "past the window's last column and row)", flag, text));
    v[k] = *n;
    from = comma + 1;
  }
  const int x0 = v[0], y0 = v[1], x1 = v[2], y1 = v[3];
  if (x1 <= x0 || y1 <= y0)
    throw std::invalid_argument(fmt::format("{} {}: empty (X1 must be more than X0, Y1 more than Y0)", flag, text));
  if (x1 > frame_width || y1 > frame_height)
    throw std::invalid_argument(fmt::format("{} {}: reaches outside the {}x{} frame (X1 at most {}, Y1 at most {})", flag,
                                            text, frame_width, frame_height, frame_width, frame_height));
  return {{x0, y0, frame_width, frame_height}, x1 - x0, y1 - y0};
}

std::pair<int, int> output_size(int width, int height, const std::optional<std::string>& size, double scale) {
  if (size) std::tie(width, height) = parse_image_size(*size, "--size");
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument(fmt::format("--scale {}: must be a positive number", scale));
  // In double, so a large --scale cannot wrap an int around before the check.
  const double w = std::round(width * scale), h = std::round(height * scale);
  if (w < 1 || h < 1 || w > max_frame_side || h > max_frame_side)
    throw std::invalid_argument(fmt::format("image size {:.0f}x{:.0f} is out of range (1 to {} a side; check --size and --scale)",
                                            w, h, max_frame_side));
  return {static_cast<int>(w), static_cast<int>(h)};
}

}  // namespace lc
