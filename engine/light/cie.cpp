#include "light/cie.hpp"

#include <algorithm>
#include <cmath>

namespace lc {

namespace {

// One lobe of the fit: a Gaussian with different widths left and right of
// its centre (nm).
double lobe(double nm, double centre, double left, double right) {
  const double s = (nm - centre) / (nm < centre ? left : right);
  return std::exp(-0.5 * s * s);
}

}  // namespace

XYZ cie_1931(double nm) {
  return {1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
              0.065 * lobe(nm, 501.1, 20.4, 26.2),
          0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1),
          1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8)};
}

std::array<double, 3> linear_srgb_exact(const XYZ& c) {
  return {3.2406 * c.X - 1.5372 * c.Y - 0.4986 * c.Z, -0.9689 * c.X + 1.8758 * c.Y + 0.0415 * c.Z,
          0.0557 * c.X - 0.2040 * c.Y + 1.0570 * c.Z};
}

Color linear_srgb(const XYZ& c) {
  const auto v = linear_srgb_exact(c);
  return {static_cast<float>(std::max(v[0], 0.0)), static_cast<float>(std::max(v[1], 0.0)),
          static_cast<float>(std::max(v[2], 0.0))};
}

}  // namespace lc
