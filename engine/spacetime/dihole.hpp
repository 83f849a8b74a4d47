#pragma once
// Extreme Reissner–Nordström dihole (Majumdar–Papapetrou with two holes,
// spacetime/extreme_holes.hpp) in Cartesian coordinates:
// U = 1 + m1/|x - x1| + m2/|x - x2|, hole 1 at (0, 0, +d), hole 2 at (0, 0, -d).
// Reference: Wünsch, Müller, Weiskopf, Wunner, Phys. Rev. D 87, 024007 (2013).
// The paper's spacetime, kept beside lc.majumdar_papapetrou (any number of
// holes anywhere) because its frames are the paper's to the bit: its
// potential's algebra, written for two holes on the axis, is not the general
// one's rounding.

#include <cmath>

#include "core/constants.hpp"
#include "core/lanes.hpp"
#include "spacetime/cartesian_scene.hpp"
#include "spacetime/extreme_holes.hpp"
#include "spacetime/model.hpp"
#include "spacetime/weak_field_tail.hpp"

namespace lc {

// No thin-disk flux is worked out for two holes (objects/disk_physics.hpp).
class Dihole : public CartesianScene,
               public ExtremeHoles<Dihole>,
               public HamiltonianFromRhs<Dihole>,
               public CartesianInfinity,
               public ObserversOutsideHorizons<Dihole> {
 public:
  static constexpr std::string_view name = "dihole";
  static constexpr SceneChart chart = SceneChart::cartesian;
  static constexpr bool stationary = true;  // static holes; see Kerr::stationary
  // Infinity, and the two holes' horizons as one end (the capture rule does
  // not tell them apart).
  static constexpr std::array ends = {SpacetimeEnd{"infinity", EndKind::infinity},
                                      SpacetimeEnd{"horizon", EndKind::horizon}};
  struct Params {
    double m1 = 0.0, m2 = 0.0, d = 1.0;
    static constexpr auto fields = std::tuple{
        field("m1", &Params::m1, std::optional<double>{}, at_least(0.0), std::nullopt, "the mass of the hole at z = +d"),
        field("m2", &Params::m2, std::optional<double>{}, at_least(0.0), std::nullopt, "the mass of the hole at z = -d"),
        field("d", &Params::d, std::optional<double>{1.0}, above(0.0), std::nullopt,
              "half the distance between the holes (the paper: 1)"),
    };
  };
  // Throws std::invalid_argument for negative or non-finite masses, d <= 0.
  Dihole(double m1, double m2, double d);
  explicit Dihole(const Params& p) : Dihole(p.m1, p.m2, p.d) {}
  Params params() const { return {m1_, m2_, d_}; }
  Dihole for_tracing(TimeDirection) const { return *this; }
  static std::vector<SpacetimeExample<Dihole>> examples() {
    return {{Dihole(0.4, 0.4, 1.0), 2.1, 40.0}, {Dihole(0.6, 0.2, 1.5), 2.6, 40.0}, {Dihole(0.0, 0.0, 1.0), 0.5, 40.0}};
  }

  double mass1() const { return m1_; }
  double mass2() const { return m2_; }
  double separation() const { return d_; }
  double asymptotic_mass() const { return m1_ + m2_; }
  // Photon orbits lie within 4 (m1 + m2) of the holes at z = +-d.
  double photon_reach() const { return 4.0 * asymptotic_mass() + d_; }
  // Where the multipoles beyond the monopole bend light by less than
  // far_field_bending: unequal holes have a dipole, (m1 - m2) d / r^2,
  // bending ~|m1 - m2| d / r^2; equal ones a quadrupole, ~M d^2 / r^3.  The
  // paper's dihole: ~93 M; masses 0.6 and 0.2: ~630 M.  The monopole's
  // bending beyond comes from weak_field_tail.hpp.
  double far_field_radius() const {
    const double M = asymptotic_mass(), dm = std::abs(m1_ - m2_);
    return std::max(std::cbrt(M * d_ * d_ / far_field_bending), std::sqrt(dm * d_ / far_field_bending));
  }
  // U and its gradient at the spatial point (X, Y, Z), T double or lanes
  // (spacetime/extreme_holes.hpp).
  template <class T>
  [[gnu::always_inline]] T potential_with_gradient(const T& X, const T& Y, const T& Z, T& gx, T& gy, T& gz) const {
    const T z1 = Z - d_, z2 = Z + d_;
    const T rho2 = X * X + Y * Y;
    const T i1 = 1.0 / sqrt_of(rho2 + z1 * z1), i2 = 1.0 / sqrt_of(rho2 + z2 * z2);
    const T U = 1.0 + m1_ * i1 + m2_ * i2;
    const T c1 = m1_ * i1 * i1 * i1, c2 = m2_ * i2 * i2 * i2;
    gx = -(c1 + c2) * X;
    gy = -(c1 + c2) * Y;
    gz = -(c1 * z1 + c2 * z2);
    return U;
  }

 private:
  double m1_, m2_, d_;
};

}  // namespace lc
