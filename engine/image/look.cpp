#include "image/look.hpp"

#include <charconv>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/fields.hpp"

namespace lc {

namespace {

// One exposed channel through a per-channel view (standard or filmic).
float channel_view(View view, double x) {
  return view == View::filmic ? static_cast<float>(filmic_curve(x)) : static_cast<float>(x);
}

// A look's numeric members by the names the shot's fields give them.
struct NumberMember {
  std::string_view name;
  double Look::*member;
};
constexpr NumberMember number_members[] = {{"exposure", &Look::exposure},
                                           {"white_balance", &Look::white_balance},
                                           {"saturation", &Look::saturation},
                                           {"bloom", &Look::bloom},
                                           {"bloom_radius", &Look::bloom_radius}};

}  // namespace

std::string look_text(const Look& look) {
  const Look plain;
  std::vector<std::string> parts;
  if (look.exposure != plain.exposure) parts.push_back(fmt::format("exposure:{}", look.exposure));
  if (look.view != plain.view) parts.push_back(fmt::format("view:{}", choice_name(look.view)));
  for (const NumberMember& m : number_members)
    if (m.name != "exposure" && look.*m.member != plain.*m.member)
      parts.push_back(fmt::format("{}:{}", m.name, look.*m.member));
  return fmt::format("{}", fmt::join(parts, ","));
}

Look parse_look_text(std::string_view text) {
  Look look;
  while (!text.empty()) {
    const std::string_view part = text.substr(0, text.find(','));
    text.remove_prefix(std::min(text.size(), part.size() + 1));
    const auto colon = part.find(':');
    if (colon == std::string_view::npos)
      throw std::invalid_argument(fmt::format("'{}': a look's part is name:value", part));
    const std::string_view name = part.substr(0, colon), value = part.substr(colon + 1);
    if (name == "view") {
      const auto names = choice_names(View{});
      const auto it = std::find(names.begin(), names.end(), value);
      if (it == names.end())
        throw std::invalid_argument(fmt::format("'{}': the view is {}", part, choices_text<View>()));
      look.view = static_cast<View>(it - names.begin());
      continue;
    }
    const auto m = std::find_if(std::begin(number_members), std::end(number_members),
                                [&](const NumberMember& n) { return n.name == name; });
    if (m == std::end(number_members))
      throw std::invalid_argument(
          fmt::format("'{}': a look has {}", part, fmt::join(look_field_names, ", ")));
    double v = 0.0;
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
    if (ec != std::errc() || end != value.data() + value.size() || !std::isfinite(v))
      throw std::invalid_argument(fmt::format("'{}': {} is not a number", part, value));
    look.*(m->member) = v;
  }
  return look;
}

FrameImage Look::applied(const FrameImage& image) const {
  FrameImage out{image.width, image.height, image.rgb, {}, {}, image.alpha};
  if (identity()) return out;
  std::vector<float>& rgb = out.rgb;
  const double scale = std::exp2(exposure);
  double after_grade = scale;  // what the view still multiplies by
  if (graded()) {
    // Bloom's threshold is the display's white, so the light is exposed first.
    if (scale != 1.0)
      for (float& v : rgb) v = static_cast<float>(v * scale);
    after_grade = 1.0;
    if (bloom != 0.0) apply_bloom(rgb, out.width, out.height, Bloom{bloom, bloom_radius, 1.0});
    if (white_balance != 0.0) apply_matrix(rgb, white_balance_matrix(white_balance));
    if (saturation != 1.0) apply_saturation(rgb, saturation);
  }
  if (view != View::gamut_safe) {
    for (float& v : rgb) v = channel_view(view, v * after_grade);
    return out;
  }
  show_gamut_safe(rgb, after_grade);
  return out;
}

}  // namespace lc
