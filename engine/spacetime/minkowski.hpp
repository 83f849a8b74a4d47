#pragma once
// Flat spacetime in Cartesian coordinates: straight rays, the control case
// every curved scene must reduce to.

#include "spacetime/cartesian_scene.hpp"

namespace lc {

class Minkowski : public CartesianScene {
 public:
  static constexpr bool stationary = true;  // see Kerr::stationary
  // Hamilton's equations on y = (x^mu, p_mu), T double or lanes: straight lines.
  template <class T>
  void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    dy = {-y[4], y[5], y[6], y[7], T{}, T{}, T{}, T{}};
  }
  void hamiltonian_rhs(const Vec4&, const Vec4& p, Vec4& dx, Vec4& dp) const {
    dx = {-p[0], p[1], p[2], p[3]};
    dp = {0.0, 0.0, 0.0, 0.0};
  }
  double asymptotic_mass() const { return 0.0; }
  bool captured(const Vec4&) const { return false; }
  double capture_margin(const Vec4&) const { return 1.0; }
  bool inside_horizon(const Vec4&) const { return false; }
  Mat4 metric(const Vec4&) const { return {{{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}; }
  Vec4 diagonal_metric(const Vec4&) const { return {-1, 1, 1, 1}; }
  Mat4 inverse_metric(const Vec4& x) const { return metric(x); }
  Mat4Derivs metric_derivatives(const Vec4&) const { return {}; }
};

}  // namespace lc
