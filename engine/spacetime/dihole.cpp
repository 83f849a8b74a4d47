#include "spacetime/dihole.hpp"

#include "spacetime/extreme_holes_impl.hpp"

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

template struct ExtremeHoles<Dihole>;

}  // namespace lc
