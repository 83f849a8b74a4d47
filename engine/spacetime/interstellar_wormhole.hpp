#pragma once
// The wormhole of the film Interstellar (James, von Tunzelmann, Franklin &
// Thorne, Am. J. Phys. 83, 486 (2015), their eqs. 5–6, the "Dneg
// wormhole"): a cylinder of radius ρ and length 2a, flaring onto two flat
// universes through a region whose gentleness a lensing width W sets,
//   r(l) = ρ                                   for |l| <= a,
//   r(l) = ρ + 𝓜 (x atan x - ln(1 + x^2)/2)    for |l| > a,
//   x = 2(|l| - a)/(π𝓜),  W = 1.42953 𝓜,
// with no pull (spacetime/morris_thorne.hpp has the family).  r is C^1 at
// |l| = a (dr/dl = (2/π) atan x sgn l); its curvature jumps there, which
// the integrator's step control meets as it meets any kink.  Every |l| <= a
// holds circular photon orbits round the cylinder: the photon region.
// James et al.'s film values are a = 0.005 ρ and W = 0.05 ρ.

#include <cmath>
#include <string_view>
#include <type_traits>

#include "core/fields.hpp"
#include "core/lanes.hpp"
#include "spacetime/model.hpp"
#include "spacetime/morris_thorne.hpp"

namespace lc {

// W / 𝓜 (James et al. 2015, below their eq. 6).
inline constexpr double interstellar_width_per_mass = 1.42953;

class InterstellarWormhole : public MorrisThorne<InterstellarWormhole>,
                             public HamiltonianFromRhs<InterstellarWormhole> {
 public:
  static constexpr std::string_view name = "interstellar_wormhole";
  static constexpr SceneChart chart = SceneChart::polar;  // (t, l, θ, φ), l signed
  static constexpr bool stationary = true;                // see Kerr::stationary
  static constexpr std::array other_names = {
      OtherName{"dneg_wormhole", "lc.interstellar_wormhole{throat = ρ, length = 2a, lensing_width = W}"}};
  struct Params {
    double throat = 0.0, length = 0.0, lensing_width = 0.0;
    static constexpr auto fields = std::tuple{
        field("throat", &Params::throat, std::optional<double>{}, above(0.0), std::nullopt,
              "the radius ρ of its cylindrical interior"),
        field("length", &Params::length, std::optional<double>{0.0}, at_least(0.0), std::nullopt,
              "the length 2a of its cylindrical interior (the film's: 0.01 ρ)"),
        field("lensing_width", &Params::lensing_width, std::optional<double>{}, above(0.0), std::nullopt,
              "W = 1.42953 𝓜, the width of the flare that lenses strongly (the film's: 0.05 ρ)")};
  };
  // Throws std::invalid_argument where ρ <= 0, 2a < 0, W <= 0 or any is not
  // finite.
  explicit InterstellarWormhole(const Params& p);
  Params params() const { return {rho_, 2.0 * a_, m_ * interstellar_width_per_mass}; }
  InterstellarWormhole for_tracing(TimeDirection) const { return *this; }
  static std::vector<SpacetimeExample<InterstellarWormhole>> examples();

  double chart_scale() const { return rho_; }
  double photon_reach() const { return a_; }

  // r(l) and dr/dl at one l.
  void shape_at(double l, double& r, double& dr) const {
    const double s = l < 0.0 ? -1.0 : 1.0, over = std::abs(l) - a_;
    if (!(over > 0.0)) {
      r = rho_;
      dr = 0.0;
      return;
    }
    const double x = over * x_per_l_, at = std::atan(x);
    r = rho_ + m_ * (x * at - 0.5 * std::log1p(x * x));
    dr = s * (2.0 / pi) * at;
  }
  // The same in lanes, one at a time (atan and log have no lane form here).
  template <class T>
  void shape(const T& l, T& r, T& dr) const {
    if constexpr (std::is_same_v<T, double>) {
      shape_at(l, r, dr);
    } else {
      for (int i = 0; i < lane_count; ++i) {
        double ri, di;
        shape_at(l[i], ri, di);
        r[i] = ri;
        dr[i] = di;
      }
    }
  }

 private:
  double rho_, a_, m_, x_per_l_;
};

}  // namespace lc
