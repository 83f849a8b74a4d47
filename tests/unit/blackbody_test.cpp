// Blackbody colours against figures of colorimetry: Planckian light at
// 2856 K is CIE illuminant A, chromaticity (0.44757, 0.40745) (CIE 15:2004);
// the Planckian locus at 6500 K is at (0.3135, 0.3237) and at 10000 K at
// (0.2807, 0.2884) (Wyszecki & Stiles, table 1(3.11)); Stefan–Boltzmann
// makes the luminance of hot light grow as T^4 only in the visible's
// Rayleigh–Jeans tail (Y ∝ T far above 30000 K).  The matching functions
// are a fit good to ~1%, so chromaticities are asked to 2e-3.

#include <gtest/gtest.h>

#include <cmath>

#include "light/blackbody.hpp"

namespace lc {
namespace {

std::pair<double, double> chromaticity(double kelvin) {
  const XYZ c = blackbody_xyz(kelvin);
  const double s = c.X + c.Y + c.Z;
  return {c.X / s, c.Y / s};
}

TEST(Blackbody, ChromaticitiesOnThePlanckianLocus) {
  for (const auto& [T, x, y] : {std::tuple{2856.0, 0.44757, 0.40745}, std::tuple{6500.0, 0.3135, 0.3237},
                                std::tuple{10000.0, 0.2807, 0.2884}}) {
    const auto [cx, cy] = chromaticity(T);
    EXPECT_NEAR(cx, x, 2e-3) << T << " K";
    EXPECT_NEAR(cy, y, 2e-3) << T << " K";
  }
}

TEST(Blackbody, ColoursGoFromRedToBlueAndTheTableFollowsTheSpectrum) {
  const BlackbodyColors colors(6500.0);
  const Color warm = colors(2000.0), white = colors(6500.0), hot = colors(30000.0);
  EXPECT_GT(warm[0], warm[2]);  // red over blue
  EXPECT_GT(hot[2], hot[0]);    // blue over red
  // The reference has luminance 1: Y = 0.2126 R + 0.7152 G + 0.0722 B.
  const auto Y = [](const Color& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
  EXPECT_NEAR(Y(white), 1.0, 2e-3);
  // The table against the integral, at temperatures between its entries.
  const double y_ref = blackbody_xyz(6500.0).Y;
  for (const double T : {150.0, 1234.5, 4321.0, 9876.0, 54321.0, 3e6}) {
    const Color direct = linear_srgb([&] {
      XYZ c = blackbody_xyz(T);
      return XYZ{c.X / y_ref, c.Y / y_ref, c.Z / y_ref};
    }());
    const Color looked_up = colors(T);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(looked_up[i], direct[i], 1e-3 * std::abs(direct[i]) + 1e-30) << T << " K";
  }
  // Far above the visible's peak, luminance grows as T.
  EXPECT_NEAR(Y(colors(2e7)) / Y(colors(1e7)), 2.0, 1e-3);
  EXPECT_EQ(colors(50.0)[1], 0.0f);
}

}  // namespace
}  // namespace lc
