#pragma once
// Extreme Reissner–Nordström dihole (Majumdar–Papapetrou) in Cartesian
// coordinates: ds^2 = -U^-2 dt^2 + U^2 (dx^2 + dy^2 + dz^2),
// U = 1 + m1/|x - x1| + m2/|x - x2|, hole 1 at (0, 0, +d), hole 2 at (0, 0, -d).
// The horizons are the coordinate points x1, x2; rays are stopped where U
// exceeds dihole_capture_potential instead of being chased towards them.
// Reference: Wünsch, Müller, Weiskopf, Wunner, Phys. Rev. D 87, 024007 (2013).

#include <cmath>

#include "core/constants.hpp"
#include "core/lanes.hpp"
#include "spacetime/cartesian_scene.hpp"
#include "spacetime/model.hpp"
#include "spacetime/weak_field_tail.hpp"

namespace lc {

// No thin-disk flux is worked out for two holes (objects/disk_physics.hpp).
class Dihole : public CartesianScene,
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
  Vec3 escape_direction(const Vec4& x, const Vec3& d) const {
    return isotropic_escape_direction({x[1], x[2], x[3]}, d, asymptotic_mass());
  }

  // Thin-disk matter at the trace event x (docs/light.md): on the circular
  // orbit about the z axis that the radial pull at x allows, anticlockwise
  // seen from +z, at x's cylindrical radius R: Omega^2 = -∂_R g_tt / ∂_R
  // g_phiphi with g_tt = -U^-2, g_phiphi = U^2 R^2 (a geodesic in the plane
  // z = 0 of equal masses; for unequal ones the plane's pull along z is
  // ignored).  At rest where no such orbit exists (it would be faster than
  // light, or the pull points outwards) and on the axis.
  Vec4 disk_velocity(const Vec4& x) const;

  // U and its gradient at a spatial point.
  double potential(const Vec4& x, Vec3* grad = nullptr) const {
    const double X = x[1], Y = x[2];
    const double z1 = x[3] - d_, z2 = x[3] + d_;
    const double rho2 = X * X + Y * Y;
    const double i1 = 1.0 / std::sqrt(rho2 + z1 * z1), i2 = 1.0 / std::sqrt(rho2 + z2 * z2);
    const double U = 1.0 + m1_ * i1 + m2_ * i2;
    if (grad) {
      const double c1 = m1_ * i1 * i1 * i1, c2 = m2_ * i2 * i2 * i2;
      *grad = {-(c1 + c2) * X, -(c1 + c2) * Y, -(c1 * z1 + c2 * z2)};
    }
    return U;
  }

  // Hamilton's equations for H = 1/2 (-U^2 p_t^2 + U^-2 |p|^2) on the state
  // y = (x^mu, p_mu).  T is double or a vector of lanes (core/lanes.hpp),
  // one ray each: the potential's algebra inline, as potential() has it.
  // Always inlined into the integrator's stages: the compiler's own choice
  // there changes with unrelated code elsewhere in the renderer
  // (docs/performance.md, change 32).
  template <class T>
  [[gnu::always_inline]] void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    const T X = y[1], Y = y[2], z1 = y[3] - d_, z2 = y[3] + d_;
    const T rho2 = X * X + Y * Y;
    const T i1 = 1.0 / sqrt_of(rho2 + z1 * z1), i2 = 1.0 / sqrt_of(rho2 + z2 * z2);
    const T U = 1.0 + m1_ * i1 + m2_ * i2;
    const T c1 = m1_ * i1 * i1 * i1, c2 = m2_ * i2 * i2 * i2;
    const T gx = -(c1 + c2) * X, gy = -(c1 + c2) * Y, gz = -(c1 * z1 + c2 * z2);
    const T iU2 = 1.0 / (U * U);
    const T p2 = y[5] * y[5] + y[6] * y[6] + y[7] * y[7];
    dy[0] = -U * U * y[4];
    dy[1] = iU2 * y[5];
    dy[2] = iU2 * y[6];
    dy[3] = iU2 * y[7];
    const T k = U * y[4] * y[4] + iU2 / U * p2;  // -dH/dU
    dy[4] = T{};
    dy[5] = k * gx;
    dy[6] = k * gy;
    dy[7] = k * gz;
  }

  bool captured(const Vec4& x) const { return potential(x) > dihole_capture_potential; }
  // A smooth function negative exactly where captured() holds (see Kerr).
  double capture_margin(const Vec4& x) const { return dihole_capture_potential - potential(x); }
  bool inside_horizon(const Vec4& x) const { return captured(x); }

  Mat4 metric(const Vec4& x) const;
  // The metric's diagonal (it has nothing else): -U^-2, U^2, U^2, U^2.
  Vec4 diagonal_metric(const Vec4& x) const {
    const double U = potential(x), U2 = U * U;
    return {-1.0 / U2, U2, U2, U2};
  }
  Mat4 inverse_metric(const Vec4& x) const;
  Mat4Derivs metric_derivatives(const Vec4& x) const;

 private:
  double m1_, m2_, d_;
};

}  // namespace lc
