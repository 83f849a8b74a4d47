#pragma once
// Colour from spectra: the CIE 1931 2° colour-matching functions and the
// XYZ -> linear sRGB (D65, Rec. 709 primaries) matrix of IEC 61966-2-1.
// The matching functions are Wyman, Sloan & Shirley's multi-lobe fit
// (JCGT 2(2), 2013, eq. 2: within ~1% of the CIE table), so no table of
// them is shipped.

#include <array>

#include "core/color.hpp"

namespace lc {

struct XYZ {
  double X, Y, Z;
};

// x̄, ȳ, z̄ at a wavelength in nm (meaningful over 360-830 nm, the range
// every integral here covers).
XYZ cie_1931(double nm);

// Linear sRGB of an XYZ, exactly (components may be negative: out of gamut).
std::array<double, 3> linear_srgb_exact(const XYZ& c);

// Linear sRGB of an XYZ; components out of the gamut (negative) become 0.
Color linear_srgb(const XYZ& c);

}  // namespace lc
