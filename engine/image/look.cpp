#include "image/look.hpp"

#include <cmath>

namespace lc {

namespace {

// One exposed channel through a per-channel view (standard or filmic).
float channel_view(View view, double x) {
  return view == View::filmic ? static_cast<float>(filmic_curve(x)) : static_cast<float>(x);
}

}  // namespace

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
  for (std::size_t p = 0; p + 2 < rgb.size(); p += 3) {
    const auto shown = gamut_safe_view({rgb[p] * after_grade, rgb[p + 1] * after_grade, rgb[p + 2] * after_grade});
    for (int i = 0; i < 3; ++i) rgb[p + static_cast<std::size_t>(i)] = static_cast<float>(shown[static_cast<std::size_t>(i)]);
  }
  return out;
}

}  // namespace lc
