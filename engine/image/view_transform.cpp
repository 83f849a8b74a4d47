#include "image/view_transform.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/grade.hpp"

namespace lc {

namespace {

constexpr double knee_start = 0.8;
constexpr double knee_limit = 0.98;  // see gamut_safe_view: a trace of every channel stays

// For a double or four (gamut_safe_view4).
template <class T>
T narkowicz(T x) {
  return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14);
}

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

namespace {

// Four doubles, and GCC's element-wise operators on them (its vector
// extension: comparisons give masks, `m ? a : b` selects by them).
typedef double Double4 __attribute__((vector_size(32)));

// gamut_safe_view (view_transform.hpp) on four colours, written once for
// whole frames and single colours alike: every branch computed and each
// lane's taken by a mask, so light it shows black is set to 0 at the end.
void gamut_safe_view4(const Double4 (&c)[3], Double4 (&out)[3]) {
  const Double4 inf = Double4{} + std::numeric_limits<double>::infinity();
  const Double4 y = rec709_luminance[0] * c[0] + rec709_luminance[1] * c[1] + rec709_luminance[2] * c[2];
  const Double4 sum = c[0] + c[1] + c[2];
  const auto shown_black = ~(y > 0.0) | ~(sum - sum == 0.0);  // x - x is 0 exactly when x is finite
  // filmic_luminance_curve(y) where y > 0
  const Double4 shown = y == inf ? Double4{} + 1.0 : narkowicz(y) * (2.43 / 2.51);
  // The largest s for which shown (1 + s v_i) stays in [0, 1] for every
  // channel; its inverse is the colour's distance to the boundary.
  const Double4 headroom = 1.0 / shown - 1.0;  // how far above the grey a channel may go, relative to it
  Double4 s_max = inf;
  Double4 v[3];
  for (int i = 0; i < 3; ++i) {
    v[i] = c[i] / y - 1.0;
    const Double4 bound = v[i] < 0.0 ? -1.0 / v[i] : (v[i] > 0.0 ? headroom / v[i] : inf);
    s_max = bound < s_max ? bound : s_max;  // std::min(s_max, bound)
  }
  const Double4 d = 1.0 / s_max;
  const Double4 span = Double4{} + (knee_limit - knee_start), x = (d - knee_start) / span;
  const Double4 knee = d > knee_start ? knee_start + span * x / (1.0 + x) : d;  // gamut_knee(d)
  const Double4 finite_s = s_max - s_max == 0.0 ? knee / d : Double4{} + 1.0;
  const Double4 s = s_max <= 0.0 ? Double4{} : finite_s;
  for (int i = 0; i < 3; ++i) {
    const Double4 o = shown * (1.0 + s * v[i]);
    const Double4 clamped = o < 0.0 ? Double4{} : (1.0 < o ? Double4{} + 1.0 : o);  // std::clamp(o, 0, 1)
    out[i] = shown_black ? Double4{} : clamped;
  }
}

}  // namespace

std::array<double, 3> gamut_safe_view(const std::array<double, 3>& c) {
  Double4 in[3], out[3];
  for (int i = 0; i < 3; ++i) in[i] = Double4{} + c[static_cast<std::size_t>(i)];
  gamut_safe_view4(in, out);
  return {out[0][0], out[1][0], out[2][0]};
}

void show_gamut_safe(std::span<float> rgb, double scale) {
  const std::size_t pixels = rgb.size() / 3;
  std::size_t p = 0;
  for (; p + 4 <= pixels; p += 4) {
    float* px = &rgb[3 * p];
    Double4 c[3], out[3];
    for (int i = 0; i < 3; ++i) c[i] = Double4{px[i] * scale, px[3 + i] * scale, px[6 + i] * scale, px[9 + i] * scale};
    gamut_safe_view4(c, out);
    for (int k = 0; k < 4; ++k)
      for (int i = 0; i < 3; ++i) px[3 * k + i] = static_cast<float>(out[i][k]);
  }
  for (; p < pixels; ++p) {  // the last one to three pixels, a lane each
    float* px = &rgb[3 * p];
    const auto shown = gamut_safe_view({px[0] * scale, px[1] * scale, px[2] * scale});
    for (int i = 0; i < 3; ++i) px[i] = static_cast<float>(shown[static_cast<std::size_t>(i)]);
  }
}

}  // namespace lc
