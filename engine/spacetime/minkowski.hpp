#pragma once
// Flat spacetime in Cartesian coordinates: straight rays, the control case
// every curved scene must reduce to.

#include <limits>

#include "spacetime/cartesian_scene.hpp"
#include "spacetime/model.hpp"

namespace lc {

class Minkowski : public CartesianScene,
                  public HamiltonianFromRhs<Minkowski>,
                  public CartesianInfinity,
                  public NoHorizon {
 public:
  static constexpr std::string_view name = "minkowski";
  static constexpr SceneChart chart = SceneChart::cartesian;
  static constexpr bool stationary = true;  // see Kerr::stationary
  static constexpr std::array ends = {SpacetimeEnd{"infinity", EndKind::infinity}};
  struct Params {
    static constexpr auto fields = std::tuple{};
  };
  Minkowski() = default;
  explicit Minkowski(const Params&) {}
  Params params() const { return {}; }
  Minkowski for_tracing(TimeDirection) const { return *this; }
  static std::vector<SpacetimeExample<Minkowski>> examples() { return {{Minkowski{}, 0.5, 40.0}}; }
  double photon_reach() const { return 0.0; }
  // Rays escape once beyond everything they could meet.
  double far_field_radius() const { return 0.0; }
  Vec3 escape_direction(const Vec4&, const Vec3& d) const { return d; }
  // Hamilton's equations on y = (x^mu, p_mu), T double or lanes: straight lines.
  template <class T>
  void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    dy = {-y[4], y[5], y[6], y[7], T{}, T{}, T{}, T{}};
  }
  double asymptotic_mass() const { return 0.0; }
  Mat4 metric(const Vec4&) const { return {{{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}; }
  Vec4 diagonal_metric(const Vec4&) const { return {-1, 1, 1, 1}; }
  Mat4 inverse_metric(const Vec4& x) const { return metric(x); }
  Mat4Derivs metric_derivatives(const Vec4&) const { return {}; }
};

}  // namespace lc
