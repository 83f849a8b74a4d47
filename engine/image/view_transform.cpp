#include "image/view_transform.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/grade.hpp"

namespace lc {

namespace {

constexpr double knee_start = 0.8;
constexpr double knee_limit = 0.98;  // see gamut_safe_view: a trace of every channel stays

double narkowicz(double x) { return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14); }

}  // namespace

double filmic_curve(double x) {
  if (!(x > 0.0)) return 0.0;
  return std::min(1.0, narkowicz(x));
}

double filmic_luminance_curve(double y) {
  if (!(y > 0.0)) return 0.0;
  if (std::isinf(y)) return 1.0;
  return narkowicz(y) * (2.43 / 2.51);
}

double gamut_knee(double d) {
  if (!(d > knee_start)) return d;
  // Reinhard's x / (1 + x) on the excess, scaled to the span left: slope 1
  // at the start, the limit only at infinity.
  const double span = knee_limit - knee_start, x = (d - knee_start) / span;
  return knee_start + span * x / (1.0 + x);
}

std::array<double, 3> gamut_safe_view(const std::array<double, 3>& c) {
  const double y = rec709_luminance[0] * c[0] + rec709_luminance[1] * c[1] + rec709_luminance[2] * c[2];
  if (!(y > 0.0) || !std::isfinite(c[0] + c[1] + c[2])) return {0.0, 0.0, 0.0};
  const double shown = filmic_luminance_curve(y);
  // The largest s for which shown (1 + s v_i) stays in [0, 1] for every
  // channel; its inverse is the colour's distance to the boundary.
  const double headroom = 1.0 / shown - 1.0;  // how far above the grey a channel may go, relative to it
  double s_max = std::numeric_limits<double>::infinity();
  std::array<double, 3> v{};
  for (int i = 0; i < 3; ++i) {
    v[i] = c[i] / y - 1.0;
    if (v[i] < 0.0) s_max = std::min(s_max, -1.0 / v[i]);
    if (v[i] > 0.0) s_max = std::min(s_max, headroom / v[i]);
  }
  double s = 1.0;
  if (s_max <= 0.0) {
    s = 0.0;  // the shown luminance is the display's white: white is all that fits
  } else if (std::isfinite(s_max)) {
    const double d = 1.0 / s_max;
    s = gamut_knee(d) / d;
  }
  std::array<double, 3> out{};
  for (int i = 0; i < 3; ++i) out[i] = std::clamp(shown * (1.0 + s * v[i]), 0.0, 1.0);
  return out;
}

}  // namespace lc
