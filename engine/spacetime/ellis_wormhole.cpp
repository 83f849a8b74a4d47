#include "spacetime/ellis_wormhole.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "spacetime/morris_thorne_impl.hpp"

namespace lc {

template struct MorrisThorne<EllisWormhole>;

EllisWormhole::EllisWormhole(const Params& p) : b_(p.throat) {
  if (!std::isfinite(b_) || !(b_ > 0.0))
    throw std::invalid_argument(fmt::format("ellis_wormhole: throat must be a finite number > 0, got {}", b_));
}

std::vector<SpacetimeExample<EllisWormhole>> EllisWormhole::examples() {
  // Trace-chart radii from deep in the other universe (l = -20 at b = 1)
  // to far in this one (l = 40).
  return {{EllisWormhole({1.0}), 0.0125, 40.0}, {EllisWormhole({2.5}), 0.1, 30.0}};
}

}  // namespace lc
