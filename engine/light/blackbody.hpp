#pragma once
// The colour of blackbody light: Planck's spectrum at temperature T through
// the CIE 1931 2° colour-matching functions, as linear sRGB (light/cie.hpp).

#include <cstddef>
#include <vector>

#include "core/color.hpp"
#include "light/cie.hpp"

namespace lc {

// CIE XYZ of the spectral radiance B_lambda(T) (W sr^-1 m^-3), integrated
// over 360-830 nm at 1 nm.  Exact to the fit; costs ~1,400 exponentials.
XYZ blackbody_xyz(double kelvin);

// blackbody_xyz(T) as linear sRGB scaled so that T = reference has
// luminance 1, from a table in log T (100 K to 1e7 K, interpolated:
// ~1e-4 relative); black below 100 K, Rayleigh–Jeans (Y ∝ T, colour fixed)
// above 1e7 K.  Cheap enough for every ray.
class BlackbodyColors {
 public:
  // reference: the temperature whose light has luminance 1 (K, > 0).
  explicit BlackbodyColors(double reference);
  Color operator()(double kelvin) const;
  std::size_t bytes() const { return table_.size() * sizeof(Entry); }

 private:
  // At t_k, log-spaced: the colour per unit luminance and the log of the
  // luminance relative to the reference (each smooth in log T, so linear
  // interpolation is good to ~1e-4 even where Y changes by 15% a step).
  struct Entry {
    Color chroma;
    double log_y;
  };
  std::vector<Entry> table_;
  double log_lo_, step_;
};

}  // namespace lc
