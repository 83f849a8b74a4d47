#include "light/blackbody.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"

namespace lc {

namespace {

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
    const XYZ m = cie_1931(nm);
    out.X += b * m.X;
    out.Y += b * m.Y;
    out.Z += b * m.Z;
  }
  return out;
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
