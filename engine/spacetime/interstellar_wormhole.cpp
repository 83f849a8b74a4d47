#include "spacetime/interstellar_wormhole.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "spacetime/morris_thorne_impl.hpp"

namespace lc {

template struct MorrisThorne<InterstellarWormhole>;

InterstellarWormhole::InterstellarWormhole(const Params& p)
    : rho_(p.throat), a_(0.5 * p.length), m_(p.lensing_width / interstellar_width_per_mass) {
  if (!std::isfinite(p.throat) || !std::isfinite(p.length) || !std::isfinite(p.lensing_width))
    throw std::invalid_argument("interstellar_wormhole: throat, length and lensing_width must be finite numbers");
  if (!(p.throat > 0.0))
    throw std::invalid_argument(fmt::format("interstellar_wormhole: throat must be > 0, got {}", p.throat));
  if (!(p.length >= 0.0))
    throw std::invalid_argument(fmt::format("interstellar_wormhole: length must be >= 0, got {}", p.length));
  if (!(p.lensing_width > 0.0))
    throw std::invalid_argument(fmt::format(
        "interstellar_wormhole: lensing_width must be > 0, got {} (a sharp-edged mouth is a small width, e.g. 0.01 "
        "throat)",
        p.lensing_width));
  x_per_l_ = 2.0 / (pi * m_);
}

std::vector<SpacetimeExample<InterstellarWormhole>> InterstellarWormhole::examples() {
  // Across the cylinder's ends (|l| = a) into both universes: from l = -1.05
  // (deeper, the self-test's fixed difference step is too coarse for the
  // flare's curvature in this chart; the other side is this one inverted)
  // to l = 40.
  return {{InterstellarWormhole({1.0, 1.0, 0.5}), 0.2, 40.0},
          {InterstellarWormhole({1.0, 0.01, 0.05}), 0.2, 40.0}};
}

}  // namespace lc
