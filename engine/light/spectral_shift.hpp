#pragma once
// What light of a texture's colour looks like seen with frequency ratio g
// (docs/light.md, "Textures seen through g").  A colour alone has no
// spectrum, so each texel is given one: the sum of three bands, Gaussian in
// log frequency, centred at 635, 535 and 460 nm with width sigma = 0.04 in
// ln nu (full width at half maximum ~9.4%, ~60 nm at 635 nm), weighted so
// that the unshifted sum has exactly the texel's colour.  Every band lies
// outside the sRGB triangle, so every colour of the gamut has a
// non-negative spectrum.  I_nu / nu^3 is invariant along a ray, so light
// of specific intensity I_nu(nu) emitted is seen as g^3 I_nu(nu / g): a
// band slides along log nu by ln g, its shape unchanged, and the colour
// seen is linear in the texel's: rgb_seen = M(g) rgb, with M(1) the
// identity.  M(g) is tabulated in log g.

#include <array>
#include <cstddef>
#include <vector>

#include "core/color.hpp"

namespace lc {

class SpectralShift {
 public:
  // The bands: centre wavelengths (nm) and width in ln nu.
  static constexpr std::array<double, 3> band_nm = {635.0, 535.0, 460.0};
  static constexpr double band_width = 0.04;
  // The table's range of g (g_min g_max = 1); beyond it every band has left
  // 360-830 nm by more than 8 widths, and the light seen is black.
  static constexpr double g_min = 0.4, g_max = 2.5;

  SpectralShift();

  // The colour seen of light whose unshifted colour is c (linear sRGB),
  // seen with frequency ratio g: the exact transformation, g^3 I_nu(nu/g),
  // whose integral over frequency is g^4 times the emitted one.
  Color operator()(const Color& c, double g) const;

  // M(g) evaluated directly (the quadrature the table is made of): M[i][k]
  // is channel i of the light of unshifted colour e_k.  For tests.
  static std::array<std::array<double, 3>, 3> matrix(double g);
  // The linear sRGB of band k seen with ratio g (times g^3), in the units
  // matrix() uses, and the bands' weights in a colour (column j: those of
  // the unit colour e_j).  For tests.
  static std::array<double, 3> band_color(int k, double g);
  static std::array<std::array<double, 3>, 3> weights();

  std::size_t bytes() const { return table_.size() * sizeof(Entry); }

 private:
  using Entry = std::array<float, 9>;  // M(g) row by row
  std::vector<Entry> table_;
  double log_lo_, step_;
};

}  // namespace lc
