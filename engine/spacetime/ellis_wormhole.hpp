#pragma once
// The Ellis wormhole (Ellis, J. Math. Phys. 14, 104 (1973); the
// "drainhole"; Morris & Thorne 1988's first example): r(l) = √(l^2 + b^2),
// a throat of radius b opening smoothly onto two flat universes, with no
// pull (spacetime/morris_thorne.hpp has the family).  Its trace chart is
// isotropic: ds^2 = -dt^2 + (1 + b^2/(4R^2))^2 |dx|^2.  The throat is its
// one photon sphere: from l a static observer sees it as a disc of angular
// radius arcsin(b / √(l^2 + b^2)).

#include <string_view>

#include "core/fields.hpp"
#include "core/lanes.hpp"
#include "spacetime/model.hpp"
#include "spacetime/morris_thorne.hpp"

namespace lc {

class EllisWormhole : public MorrisThorne<EllisWormhole>, public HamiltonianFromRhs<EllisWormhole> {
 public:
  static constexpr std::string_view name = "ellis_wormhole";
  static constexpr SceneChart chart = SceneChart::polar;  // (t, l, θ, φ), l signed
  static constexpr bool stationary = true;                // see Kerr::stationary
  static constexpr std::array other_names = {
      OtherName{"wormhole", "lc.ellis_wormhole{throat = b} or lc.interstellar_wormhole{throat = ..., length = ..., "
                            "lensing_width = ...}"},
      OtherName{"morris_thorne", "lc.ellis_wormhole{throat = b} (r = √(l² + b²)) or lc.interstellar_wormhole{...}"},
      OtherName{"drainhole", "lc.ellis_wormhole{throat = b}"}};
  struct Params {
    double throat = 0.0;
    static constexpr auto fields = std::tuple{
        field("throat", &Params::throat, std::optional<double>{}, above(0.0), std::nullopt,
              "the throat's radius b (its circumference over 2π): r(l) = √(l² + b²)")};
  };
  // Throws std::invalid_argument where b <= 0 or is not finite.
  explicit EllisWormhole(const Params& p);
  Params params() const { return {b_}; }
  EllisWormhole for_tracing(TimeDirection) const { return *this; }
  static std::vector<SpacetimeExample<EllisWormhole>> examples();

  double throat() const { return b_; }
  double chart_scale() const { return b_; }
  // The throat, l = 0, is its one photon orbit.
  double photon_reach() const { return 0.0; }

  template <class T>
  void shape(const T& l, T& r, T& dr) const {
    r = sqrt_of(l * l + b_ * b_);
    dr = l / r;
  }

 private:
  double b_;
};

}  // namespace lc
