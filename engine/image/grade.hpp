#pragma once
// A grade: the colour operations of a film "look" (white balance, saturation,
// bloom), applied to a finished frame before it is encoded.  Each works on
// scene-linear light with Rec. 709 / sRGB primaries (docs/light.md): values
// above 1 are ordinary (bright light, not clipped yet), and components may be
// negative (colours outside the sRGB gamut, as linear_srgb_exact gives them).
// Every operation passes such light through and, given finite input, never
// produces NaN.  All are pure functions of their arguments.

#include <array>
#include <vector>

#include "core/mat3.hpp"
#include "light/cie.hpp"

namespace lc {

// Rec. 709 luminance weights (IEC 61966-2-1), used by saturation and bloom.
inline constexpr std::array<double, 3> rec709_luminance = {0.2126, 0.7152, 0.0722};

// The D65 white every white balance adapts to: the XYZ, scaled to Y = 1, of
// linear sRGB grey (r = g = b) through the XYZ -> sRGB matrix the code uses
// (light/cie.hpp).  Its chromaticity is IEC 61966-2-1's (0.3127, 0.3290) to
// the matrix's 4-digit rounding (~1e-4); it, not that chromaticity, is the
// white that comes out exactly grey.
XYZ srgb_white_xyz();

// White balance from a white given by its chromaticity (x, y) (y > 0, both
// finite; std::invalid_argument otherwise): the 3x3 matrix on linear sRGB that
// makes light of that chromaticity appear as srgb_white_xyz(), by the
// Bradford chromatic adaptation transform.  Luminance of the white is kept.
Mat3 white_balance_matrix_from_xy(double x, double y);

// White balance: the 3x3 matrix on linear sRGB that makes the white of a
// blackbody at `kelvin` (its chromaticity: light/blackbody.hpp's blackbody_xyz)
// appear as D65 white (srgb_white_xyz()), by the Bradford chromatic
// adaptation transform (Lam 1985; the von Kries scaling in Bradford's cone
// space, in its linear form as ICC.1:2010 Annex E uses it).
// kelvin in [1000, 40000] (std::invalid_argument otherwise, naming the value).
// Luminance of the adapted white is kept (Y of the source white -> same Y).
Mat3 white_balance_matrix(double kelvin);

// Applies m to every pixel of interleaved rgb (3 floats per pixel;
// std::invalid_argument if rgb.size() is not a multiple of 3).
void apply_matrix(std::vector<float>& rgb, const Mat3& m);

// Saturation about each pixel's Rec.709 luminance: c' = Y + s (c - Y).
// s >= 0 and finite (std::invalid_argument otherwise, or if rgb.size() is not
// a multiple of 3); s = 1 changes nothing (exactly: returns early), 0 gives
// grey.  Luminance is kept.
void apply_saturation(std::vector<float>& rgb, double s);

// Bloom: an energy-conserving glow of bright light.
struct Bloom {
  double strength = 0.0;   // share of the light above the threshold that is spread (0 = off, at most 1)
  double radius = 0.01;    // the glow's Gaussian sigma as a fraction of the image's diagonal
  double threshold = 1.0;  // luminance above which light blooms (in the units of the image given)
};

// Spreads `strength` of each pixel's light above `threshold` (per pixel: the share
// max(0, Y - threshold)/Y of its rgb, Y its Rec.709 luminance; pixels with Y <= 0 do not bloom)
// over a Gaussian of sigma = radius * diagonal pixels, separably (rows then columns),
// renormalised at the frame's edges so that no light leaves the frame: the sum of every
// channel over the image is unchanged (to float rounding). strength = 0 returns without touching rgb.
// width*height*3 == rgb.size() is required, width, height >= 0, strength in [0, 1],
// radius >= 0 and threshold >= 0, all finite (std::invalid_argument otherwise).
void apply_bloom(std::vector<float>& rgb, int width, int height, const Bloom& bloom);

}  // namespace lc
