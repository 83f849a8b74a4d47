#pragma once
// The sRGB transfer curve (IEC 61966-2-1), written out here rather than
// taken from OpenImageIO's colour management: frames and textures then
// encode and decode identically whatever OCIO configuration the machine has,
// and the hot code never touches OIIO.

#include <cmath>
#include <cstdint>

namespace lc {

// Linear value -> sRGB-encoded value, both nominally in [0, 1]; values
// outside that range follow the curve's formula (no clamping here).
inline double linear_to_srgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

// sRGB-encoded value in [0, 1] -> linear value; inverse of linear_to_srgb.
inline double srgb_to_linear(double s) { return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4); }

// Linear value -> 8-bit sRGB code: transfer curve, clamp to [0, 255], round
// to nearest.  NaN maps to 0 so a bad pixel shows black, not a random code.
inline std::uint8_t linear_to_srgb8(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 255;
  return static_cast<std::uint8_t>(std::lround(255.0 * linear_to_srgb(c)));
}

// Linear value -> 16-bit sRGB code, as linear_to_srgb8 on [0, 65535].
inline std::uint16_t linear_to_srgb16(float c) {
  if (!(c > 0.0f)) return 0;  // also NaN
  if (c >= 1.0f) return 65535;
  return static_cast<std::uint16_t>(std::lround(65535.0 * linear_to_srgb(c)));
}

// 8-bit sRGB code -> linear value.
inline float srgb8_to_linear(std::uint8_t code) { return static_cast<float>(srgb_to_linear(code / 255.0)); }

}  // namespace lc
