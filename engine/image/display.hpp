#pragma once
// How a frame's linear light becomes what a screen shows: the PNG (and so
// the video and the contact sheet, made from the PNGs) holds the linear
// values times 2^exposure through a tone curve, then the sRGB transfer
// curve; the EXR keeps the linear values as traced (docs/light.md).

#include <algorithm>
#include <cmath>
#include <string_view>

#include "image/frame_image.hpp"

namespace lc {

enum class ToneCurve {
  clip,    // values above 1 show as 1 (the paper's look: its textures stay below 1)
  filmic,  // a film-like shoulder: highlights compress instead of clipping
};

struct DisplayTransform {
  double exposure = 0.0;  // stops
  ToneCurve curve = ToneCurve::clip;

  bool identity() const { return exposure == 0.0 && curve == ToneCurve::clip; }

  // One linear channel value -> the linear value to encode as sRGB (in
  // [0, 1] for the filmic curve; clip leaves the clamping to the encoder).
  // The filmic curve is Narkowicz's fit of the ACES reference rendering
  // transform (2015, "ACES Filmic Tone Mapping Curve"):
  //   f(x) = x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14),
  // f(0) = 0, f(1) = 0.80, f -> 1.03 (clamped to 1) for bright light.
  float operator()(float linear) const {
    const double x = linear * std::exp2(exposure);
    if (curve == ToneCurve::clip) return static_cast<float>(x);
    if (!(x > 0.0)) return 0.0f;
    return static_cast<float>(std::min(1.0, x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)));
  }

  // The image's colours through the transform (its layers dropped: the
  // PNG has none).
  FrameImage applied(const FrameImage& image) const {
    FrameImage out{image.width, image.height, image.rgb, {}, {}, image.alpha};
    if (!identity()) std::transform(out.rgb.begin(), out.rgb.end(), out.rgb.begin(), *this);
    return out;
  }
};

}  // namespace lc
