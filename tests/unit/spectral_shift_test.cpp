// The spectra textures are given (light/spectral_shift.hpp): every colour
// of the sRGB gamut is a non-negative spectrum; unshifted, the table gives
// the texture back; a band shifted by the ratio of two bands' centres is
// the other band times g^3 (a shift slides a band along log nu, its shape
// unchanged, and I_nu / nu^3 is invariant); the table agrees with the
// quadrature it is made of; light shifted out of the visible is black.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "light/spectral_shift.hpp"

namespace lc {
namespace {

Color to_color(const std::array<double, 3>& v) {
  return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}
float largest(const Color& c) { return std::max({std::abs(c[0]), std::abs(c[1]), std::abs(c[2])}); }

TEST(SpectralShift, EveryColourOfTheGamutHasANonNegativeSpectrum) {
  // The weights of the bands in each unit colour are >= 0, so those of any
  // non-negative colour are.
  for (const auto& row : SpectralShift::weights())
    for (const double w : row) EXPECT_GE(w, 0.0);
}

TEST(SpectralShift, UnshiftedLightIsTheTexture) {
  // Tolerance 1e-5 relative: the table holds floats.
  const SpectralShift shift;
  for (const Color c : {Color{1, 0, 0}, Color{0, 1, 0}, Color{0, 0, 1}, Color{0.35f, 0.12f, 0.03f}, Color{1, 1, 1}}) {
    const Color s = shift(c, 1.0);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(s[i], c[i], 1e-5 * largest(c)) << i;
  }
}

TEST(SpectralShift, ABandShiftedOntoAnotherIsThatBand) {
  // Band k seen with g = lambda_k / lambda_j has its centre at lambda_j:
  // it is band j times g^3.  Tolerance 1e-3 of the largest component: the
  // table is interpolated linearly in log g (steps of 4.5% of a band's
  // width).
  const SpectralShift shift;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j) {
      const double g = SpectralShift::band_nm[k] / SpectralShift::band_nm[j];
      const Color band_k = to_color(SpectralShift::band_color(k, 1.0));
      const Color band_j = to_color(SpectralShift::band_color(j, 1.0));
      // Components below 0 (out of the gamut) are kept, as the light's.
      const Color seen = shift(band_k, g);
      for (int i = 0; i < 3; ++i) {
        const double expected = g * g * g * band_j[i];
        EXPECT_NEAR(seen[i], expected, 1e-3 * g * g * g * largest(band_j)) << "band " << k << " onto " << j << " channel " << i;
      }
    }
}

TEST(SpectralShift, TheTableAgreesWithItsQuadrature) {
  // Tolerance 1e-3 of the largest component (linear interpolation in log g),
  // and 1e-6 of the unshifted light where the bands' tails are all that is
  // left.
  const SpectralShift shift;
  const Color c = {0.8f, 0.5f, 0.2f};
  for (double g = 0.45; g < 2.45; g *= 1.0713) {
    const auto m = SpectralShift::matrix(g);
    const Color seen = shift(c, g);
    double scale = 0.0;
    for (int i = 0; i < 3; ++i) scale = std::max(scale, std::abs(m[i][0] * c[0] + m[i][1] * c[1] + m[i][2] * c[2]));
    for (int i = 0; i < 3; ++i) {
      const double expected = m[i][0] * c[0] + m[i][1] * c[1] + m[i][2] * c[2];
      EXPECT_NEAR(seen[i], expected, 1e-3 * scale + 1e-6 * largest(c)) << "g " << g << " channel " << i;
    }
  }
}

TEST(SpectralShift, ShiftsMoveColoursAlongTheSpectrum) {
  // Red light blueshifted a little turns orange-yellow (green grows against
  // red); blue light redshifted turns towards cyan-green.
  const SpectralShift shift;
  const Color red = shift({1, 0, 0}, 1.08), blue = shift({0, 0, 1}, 0.92);
  EXPECT_GT(red[1] / red[0], 0.2f);
  EXPECT_GT(blue[1] / blue[2], 0.2f);
}

TEST(SpectralShift, LightShiftedOutOfTheVisibleIsBlack) {
  // At the table's ends every band is more than 8 widths beyond 360-830 nm:
  // below 1e-6 of the unshifted light; beyond them exactly black.
  const SpectralShift shift;
  const Color white = {1, 1, 1};
  for (const double g : {SpectralShift::g_min, SpectralShift::g_max}) EXPECT_LT(largest(shift(white, g)), 1e-6f) << g;
  for (const double g : {0.3, 3.0, 0.0, 1e300}) {
    const Color c = shift(white, g);
    EXPECT_EQ(largest(c), 0.0f) << g;
  }
}

}  // namespace
}  // namespace lc
