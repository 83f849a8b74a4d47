#include "light/blackbody.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"

namespace lc {

namespace {

// One lobe of the fit: a Gaussian with different widths left and right of
// its centre (nm).
double lobe(double nm, double centre, double left, double right) {
  const double s = (nm - centre) / (nm < centre ? left : right);
  return std::exp(-0.5 * s * s);
}
// CIE 1931 2° matching functions, Wyman, Sloan & Shirley (2013), eq. 2.
double x_bar(double nm) {
  return 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7) -
         0.065 * lobe(nm, 501.1, 20.4, 26.2);
}
double y_bar(double nm) { return 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1); }
double z_bar(double nm) { return 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8); }

constexpr double table_lo = 100.0, table_hi = 1e7;  // K
constexpr int table_size = 2048;

}  // namespace

XYZ blackbody_xyz(double kelvin) {
  XYZ out{0.0, 0.0, 0.0};
  if (!(kelvin > 0.0)) return out;
  const double c1 = 2.0 * planck_h * speed_of_light * speed_of_light;
  const double c2 = planck_h * speed_of_light / boltzmann_k;
  for (int nm = 360; nm <= 830; ++nm) {
    const double l = nm * 1e-9;
    const double b = c1 / (l * l * l * l * l) / std::expm1(c2 / (l * kelvin)) * 1e-9;  // per nm
    out.X += b * x_bar(nm);
    out.Y += b * y_bar(nm);
    out.Z += b * z_bar(nm);
  }
  return out;
}

Color linear_srgb(const XYZ& c) {
  const double r = 3.2406 * c.X - 1.5372 * c.Y - 0.4986 * c.Z;
  const double g = -0.9689 * c.X + 1.8758 * c.Y + 0.0415 * c.Z;
  const double b = 0.0557 * c.X - 0.2040 * c.Y + 1.0570 * c.Z;
  return {static_cast<float>(std::max(r, 0.0)), static_cast<float>(std::max(g, 0.0)),
          static_cast<float>(std::max(b, 0.0))};
}

BlackbodyColors::BlackbodyColors(double reference)
    : log_lo_(std::log(table_lo)), step_((std::log(table_hi) - std::log(table_lo)) / (table_size - 1)) {
  if (!(reference > 0.0) || !std::isfinite(reference))
    throw std::invalid_argument(fmt::format("a blackbody's reference temperature must be > 0 K, got {}", reference));
  const double y_ref = blackbody_xyz(reference).Y;
  table_.resize(table_size);
  for (int k = 0; k < table_size; ++k) {
    const XYZ c = blackbody_xyz(std::exp(log_lo_ + k * step_));
    table_[k] = {linear_srgb({c.X / c.Y, 1.0, c.Z / c.Y}), std::log(c.Y / y_ref)};
  }
}

Color BlackbodyColors::operator()(double kelvin) const {
  if (!(kelvin >= table_lo)) return {0.0f, 0.0f, 0.0f};
  const double u = (std::log(kelvin) - log_lo_) / step_;
  if (u >= table_size - 1) {
    const Entry& e = table_.back();
    const float y = static_cast<float>(std::exp(e.log_y) * kelvin / table_hi);
    return {e.chroma[0] * y, e.chroma[1] * y, e.chroma[2] * y};
  }
  const int k = static_cast<int>(u);
  const double w = u - k;
  const Entry &a = table_[k], &b = table_[k + 1];
  const float y = static_cast<float>(std::exp(a.log_y + w * (b.log_y - a.log_y)));
  const float wf = static_cast<float>(w);
  Color out;
  for (int i = 0; i < 3; ++i) out[i] = y * (a.chroma[i] + wf * (b.chroma[i] - a.chroma[i]));
  return out;
}

}  // namespace lc
