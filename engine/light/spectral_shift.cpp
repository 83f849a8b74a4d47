#include "light/spectral_shift.hpp"

#include <algorithm>
#include <cmath>

#include "core/mat3.hpp"
#include "light/cie.hpp"

namespace lc {

namespace {

constexpr int table_size = 1025;  // odd: g = 1 (the middle, as g_min g_max = 1) is a node

// The matching functions at 360, 361, ..., 830 nm.
using MatchingTable = std::array<XYZ, 471>;
MatchingTable matching_table() {
  MatchingTable t;
  for (std::size_t k = 0; k < t.size(); ++k) t[k] = cie_1931(360.0 + static_cast<double>(k));
  return t;
}

// The band centred at frequency c / centre_nm, shifted by g (its centre at
// g c / centre_nm) and scaled by g^3, as I_lambda = I_nu c / lambda^2 over
// 360-830 nm at 1 nm (the trapezoid rule; the band is ~60 nm wide), through
// the matching functions.  Common constant factors are left out: they
// cancel in M(g).
XYZ band_xyz(const MatchingTable& cmf, double centre_nm, double g) {
  XYZ out{0.0, 0.0, 0.0};
  const double s = SpectralShift::band_width;
  for (std::size_t k = 0; k < cmf.size(); ++k) {
    const double nm = 360.0 + static_cast<double>(k);
    // ln(nu / (g nu_c)) = ln(centre_nm / (g nm))
    const double x = std::log(centre_nm / (g * nm)) / s;
    const double w = (k == 0 || k + 1 == cmf.size() ? 0.5 : 1.0) * g * g * g * std::exp(-0.5 * x * x) / (nm * nm);
    out.X += w * cmf[k].X;
    out.Y += w * cmf[k].Y;
    out.Z += w * cmf[k].Z;
  }
  return out;
}

// C(g): column k is band k's colour seen with ratio g.
Mat3 bands(const MatchingTable& cmf, double g) {
  Mat3 c{};
  for (std::size_t k = 0; k < 3; ++k) {
    const auto rgb = linear_srgb_exact(band_xyz(cmf, SpectralShift::band_nm[k], g));
    for (int i = 0; i < 3; ++i) c[i][k] = rgb[i];
  }
  return c;
}

}  // namespace

std::array<double, 3> SpectralShift::band_color(int k, double g) {
  return linear_srgb_exact(band_xyz(matching_table(), band_nm[static_cast<std::size_t>(k)], g));
}

std::array<std::array<double, 3>, 3> SpectralShift::weights() { return inverse(bands(matching_table(), 1.0)); }

std::array<std::array<double, 3>, 3> SpectralShift::matrix(double g) {
  // The weights of the bands in a colour c are W c, W = C(1)^-1; seen
  // shifted, they give C(g) W c.
  const MatchingTable cmf = matching_table();
  const Mat3 w = inverse(bands(cmf, 1.0));
  const Mat3 cg = bands(cmf, g);
  Mat3 m{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) m[i][j] += cg[i][k] * w[k][j];
  return m;
}

SpectralShift::SpectralShift()
    : log_lo_(std::log(g_min)), step_((std::log(g_max) - std::log(g_min)) / (table_size - 1)) {
  const MatchingTable cmf = matching_table();
  const Mat3 w = inverse(bands(cmf, 1.0));
  table_.resize(table_size);
  for (int t = 0; t < table_size; ++t) {
    const Mat3 cg = bands(cmf, std::exp(log_lo_ + t * step_));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        double m = 0.0;
        for (int k = 0; k < 3; ++k) m += cg[i][k] * w[k][j];
        table_[static_cast<std::size_t>(t)][static_cast<std::size_t>(3 * i + j)] = static_cast<float>(m);
      }
  }
}

Color SpectralShift::operator()(const Color& c, double g) const {
  const double u = (std::log(g) - log_lo_) / step_;
  if (!(u >= 0.0) || !(u <= table_size - 1)) return {0.0f, 0.0f, 0.0f};
  const int k = std::min(static_cast<int>(u), table_size - 2);
  const float w = static_cast<float>(u - k);
  const Entry &a = table_[static_cast<std::size_t>(k)], &b = table_[static_cast<std::size_t>(k + 1)];
  Color out;
  for (int i = 0; i < 3; ++i) {
    float v = 0.0f;
    for (int j = 0; j < 3; ++j) {
      const float m = a[3 * i + j] + w * (b[3 * i + j] - a[3 * i + j]);
      v += m * c[j];
    }
    out[i] = v;  // below 0: outside the sRGB gamut, kept (the view transform compresses it)
  }
  return out;
}

}  // namespace lc
