#pragma once
// The view transform: how one pixel's scene-linear light, already scaled by
// the exposure and graded (image/look.hpp), becomes the linear display light
// the sRGB encoder writes (docs/light.md, "Exposure, look and view").
// Assumes linear sRGB (Rec. 709 primaries, D65) whose components may be
// negative (colours outside that gamut) or far above 1.

#include <array>
#include <span>
#include <string_view>

namespace lc {

enum class View {
  standard,    // the values as they are; the encoder clips to [0, 1] per channel (the paper's look)
  filmic,      // Narkowicz's ACES fit per channel: highlights roll off, saturated light can flip hue
  gamut_safe,  // a tone curve on luminance, then the colour desaturated towards white until it fits
};
constexpr std::array<std::string_view, 3> choice_names(View) { return {"standard", "filmic", "gamut_safe"}; }

// Narkowicz's fit of the ACES reference rendering transform (2015, "ACES
// Filmic Tone Mapping Curve"): f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59)
// + 0.14); 0 for x <= 0 (and NaN), clamped to 1 (f -> 1.033 for bright
// light; f(1) = 0.80).  The `filmic` view, channel by channel.
double filmic_curve(double x);

// The same curve divided by its limit 2.51 / 2.43, so that it approaches 1
// and reaches it only at infinity: increasing for x >= 0 (its derivative's
// numerator, 1.408 x^2 + 0.7028 x + 0.0042, is positive), 0.775 at 1.
// The gamut_safe view's tone curve, applied to luminance.
double filmic_luminance_curve(double y);

// The gamut_safe view of one colour c (exposed linear light).  With Y its
// Rec. 709 luminance and v = c / Y - 1 its chroma relative to Y:
//   1. Y' = filmic_luminance_curve(Y), so the display's luminance is a
//      monotone function of the light's;
//   2. the colour shown is Y' (1 + s v): on the line from white through c
//      (its hue, its dominant wavelength, kept), with s in (0, 1] chosen so
//      every channel is in [0, 1]: with d the colour's distance to the
//      display's gamut boundary along that line (d = 1 on it, more outside),
//      s = k(d) / d with k a soft knee: k(d) = d up to 0.8, then
//      0.8 + 0.18 x / (1 + x), x = (d - 0.8) / 0.18 (the ACES reference
//      gamut compression's Reinhard form, Academy 2021), which approaches
//      0.98 as d goes to infinity.  So every channel keeps at least 2% of
//      Y': a pixel with a channel above 8-bit 128 (Y' >= 0.0722 x 0.216)
//      has none at 8-bit 0, and the display's primaries themselves
//      (d = 1) are shown 10% desaturated.
// Light bright enough (Y' near 1) or saturated beyond the gamut thus fades
// towards white instead of clipping channel by channel, and Y' (1 + s v)
// has luminance Y' exactly.  Light with Y <= 0 (or NaN) shows black.
// Colours well inside the gamut (d <= 0.8) keep their chroma exactly.
std::array<double, 3> gamut_safe_view(const std::array<double, 3>& c);

// gamut_safe_view of every pixel of interleaved rgb (3 floats a pixel),
// each channel first times `scale` (the exposure not yet applied), in
// place, rounded to float: gamut_safe_view pixel by pixel, four pixels at
// a time in vector registers (gamut_safe_view itself is that computation
// on one colour, so the two are one definition).
void show_gamut_safe(std::span<float> rgb, double scale);

// The knee of gamut_safe_view, exposed for tests.
double gamut_knee(double d);

}  // namespace lc
