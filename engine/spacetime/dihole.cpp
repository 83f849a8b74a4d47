#include "spacetime/dihole.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace lc {

Dihole::Dihole(double m1, double m2, double d) : m1_(m1), m2_(m2), d_(d) {
  if (!std::isfinite(m1) || !std::isfinite(m2) || !std::isfinite(d))
    throw std::invalid_argument("dihole: masses and separation must be finite numbers");
  if (m1 < 0.0 || m2 < 0.0)
    throw std::invalid_argument(fmt::format("dihole: masses must be >= 0, got m1 = {}, m2 = {}", m1, m2));
  if (d <= 0.0) throw std::invalid_argument(fmt::format("dihole: d must be > 0, got {}", d));
}

Mat4 Dihole::metric(const Vec4& x) const {
  const double U = potential(x);
  Mat4 g{};
  g[0][0] = -1.0 / (U * U);
  g[1][1] = g[2][2] = g[3][3] = U * U;
  return g;
}

Mat4 Dihole::inverse_metric(const Vec4& x) const {
  const double U = potential(x);
  Mat4 g{};
  g[0][0] = -U * U;
  g[1][1] = g[2][2] = g[3][3] = 1.0 / (U * U);
  return g;
}

Mat4Derivs Dihole::metric_derivatives(const Vec4& x) const {
  Vec3 grad;
  const double U = potential(x, &grad);
  Mat4Derivs d{};
  for (int j = 0; j < 3; ++j) {
    d[j + 1][0][0] = 2.0 * grad[j] / (U * U * U);
    d[j + 1][1][1] = d[j + 1][2][2] = d[j + 1][3][3] = 2.0 * U * grad[j];
  }
  return d;
}

}  // namespace lc
