#pragma once
// Schwarzschild–de Sitter (Kottler 1918): a hole of mass M in a universe
// with a cosmological constant Λ > 0.  Static coordinates (t, r, θ, φ),
// ds^2 = -F dt^2 + dr^2/F + r^2 dΩ^2 with F = 1 - 2M/r - Λr^2/3, are the
// scene's (the polar scene chart, as Kerr's Boyer–Lindquist); the static
// region lies between the hole's horizon r_b and the cosmological horizon
// r_c, the two positive roots of F.  Rays are traced in Cartesian
// Kerr–Schild form, g = η + h l⊗l with h = 1 - F = 2M/r + Λr^2/3 and
// l = (±1, x/r, y/r, z/r) (Kerr–Schild with a flat background for any
// h(r); e.g. Gibbons, Lü, Page & Pope, J. Geom. Phys. 53, 49 (2005) for the
// family), regular across both horizons.  There is no far region where
// g_tt -> -1: a ray that leaves the static region outwards ends at the
// cosmological horizon (the outer stop rule, flight() below) and sees the
// sky painted there.

#include <cmath>
#include <limits>
#include <string_view>

#include "core/fields.hpp"
#include "core/lanes.hpp"
#include "core/tensor.hpp"
#include "spacetime/model.hpp"

namespace lc {

class Kottler : public HamiltonianFromRhs<Kottler> {
 public:
  static constexpr std::string_view name = "kottler";
  static constexpr SceneChart chart = SceneChart::polar;  // static (t, r, θ, φ)
  static constexpr bool stationary = true;                // see Kerr::stationary
  // The cosmological horizon, where escaping rays end and the scene's sky
  // is, and the hole's horizon.
  static constexpr std::array ends = {SpacetimeEnd{"cosmological horizon", EndKind::cosmological_horizon},
                                      SpacetimeEnd{"horizon", EndKind::horizon}};
  static constexpr std::array other_names = {
      OtherName{"schwarzschild_de_sitter", "lc.kottler{mass = M, lambda = L}"},
      OtherName{"de_sitter", "lc.kottler{mass = 0, lambda = L}"}};
  struct Params {
    double mass = 0.0, lambda = 0.0;
    static constexpr auto fields = std::tuple{
        field("mass", &Params::mass, std::optional<double>{}, at_least(0.0), std::nullopt, "the hole's mass M"),
        // No declared range: the constructor's refusal of Λ <= 0 says what
        // Λ = 0 is written as.
        field("lambda", &Params::lambda, std::optional<double>{}, std::nullopt, std::nullopt,
              "the cosmological constant Λ > 0, 9 Λ M^2 < 1 (a static region between the horizons); Λ = 0 is "
              "lc.kerr{mass = M}",
              "M^-2"),
    };
  };
  // Throws std::invalid_argument where M < 0, Λ <= 0, 9 Λ M^2 >= 1 (no
  // static region) or either is not finite.  sense: the Kerr–Schild chart
  // (l_t = +1 ingoing, -1 outgoing, as Kerr's).
  Kottler(double mass, double lambda, double sense = -1.0);
  explicit Kottler(const Params& p) : Kottler(p.mass, p.lambda) {}
  Params params() const { return {M_, lambda_}; }
  // The outgoing chart (regular on the hole's past horizon, where rays
  // traced into the past fall) for the past, the ingoing one for the future.
  Kottler for_tracing(TimeDirection d) const { return Kottler(M_, lambda_, d == TimeDirection::future ? 1.0 : -1.0); }
  static std::vector<SpacetimeExample<Kottler>> examples();

  double mass() const { return M_; }
  double lambda() const { return lambda_; }
  double asymptotic_mass() const { return M_; }
  // The horizons (r_b = 0 for M = 0) and the static radius (3M/Λ)^(1/3),
  // where a body at rest is in free fall: F is largest there.
  double horizon_radius() const { return r_b_; }
  double cosmological_horizon_radius() const { return r_c_; }
  double static_radius() const { return std::cbrt(3.0 * M_ / lambda_); }
  // The photon sphere r = 3M, whatever Λ (Λ drops out of the orbit equation
  // (du/dφ)^2 = 1/b^2 + Λ/3 - u^2 + 2 M u^3).
  double photon_sphere_radius() const { return 3.0 * M_; }
  double capture_radius() const { return r_capture_; }
  // Where escaping rays stop: F = kottler_stop_lapse2 below the cosmological
  // horizon (docs/physics.md).
  double stop_radius() const { return r_stop_; }
  // F(r) = -g_tt of the static chart.
  double lapse2(double r) const { return 1.0 - 2.0 * M_ / r - lambda3_ * r * r; }

  double photon_reach() const { return 3.0 * M_; }
  // No far field: rays are integrated to the cosmological horizon.
  double far_field_radius() const { return std::numeric_limits<double>::infinity(); }
  // Where the ray leaving x along d meets the cosmological horizon, carried
  // straight from x (the remaining bending, ~2M/r of the short way left, is
  // neglected; Λ bends no orbit): the sky's point, as a unit vector.
  Vec3 escape_direction(const Vec4& x, const Vec3& d) const;

  // The outer stop rule: a ray moving outwards has escaped, to end 0, past
  // the stop radius; it is free (relaxed tolerances) past radii.free2.  The
  // escape radius of radii is not used: the sky is at the horizon.
  template <class Y, class D>
  Flight flight(const Y& y, const D& dy, const FlightRadii& radii) const {
    const double rho2 = y(1) * y(1) + y(2) * y(2) + y(3) * y(3);
    if (!(rho2 > radii.free2) && !(rho2 > r_stop2_)) return {};  // the slope is not read
    const bool outward = y(1) * dy(1) + y(2) * dy(2) + y(3) * dy(3) > 0.0;
    return {rho2 > radii.free2 && outward, rho2 > r_stop2_ && outward, 0};
  }
  // The sky's light is measured against a source at rest at the static
  // radius, the one static observer in free fall: √F there,
  // √(1 - (9 Λ M^2)^(1/3)) (1 for de Sitter, M = 0, at its centre).
  double sky_source_lapse(std::size_t) const { return sky_lapse_; }
  // flight()'s measure is the Cartesian radius, as CartesianInfinity's.
  static double flight_reach(double, double hi) { return hi; }

  bool captured(const Vec4& x) const { return M_ > 0.0 && radius(x) < r_capture_; }
  double capture_margin(const Vec4& x) const { return M_ > 0.0 ? radius(x) - r_capture_ : 1.0; }
  bool inside_horizon(const Vec4& x) const { return M_ > 0.0 && radius(x) <= r_b_; }
  std::string_view why_no_observer(const Vec4& x) const {
    if (inside_horizon(x)) return "inside the hole's horizon";
    if (radius(x) >= r_c_) return "on or beyond the cosmological horizon, where nothing can stay at rest";
    return {};
  }

  // Hamilton's equations for H = 1/2 (η^{μν} - h l^μ l^ν) p_μ p_ν on the
  // state y = (x^μ, p_μ), T double or lanes (core/lanes.hpp).  As Kerr's at
  // a = 0 with h = 2M/r + Λr^2/3.  Assumes r > 0.
  template <class T>
  void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    const T X = y[1], Y = y[2], Z = y[3];
    const T r = sqrt_of(X * X + Y * Y + Z * Z);
    const T inv_r = 1.0 / r;
    const T nx = X * inv_r, ny = Y * inv_r, nz = Z * inv_r;
    const T h = 2.0 * M_ * inv_r + lambda3_ * r * r;
    const T dh = -2.0 * M_ * inv_r * inv_r + 2.0 * lambda3_ * r;
    const T np = nx * y[5] + ny * y[6] + nz * y[7];
    // L = l^μ p_μ, l^t = -l_t.
    const T L = -sense_ * y[4] + np;
    dy[0] = -y[4] + sense_ * h * L;
    dy[1] = y[5] - h * L * nx;
    dy[2] = y[6] - h * L * ny;
    dy[3] = y[7] - h * L * nz;
    // -∂_i H = 1/2 h' n_i L^2 + h L (p_i - (n.p) n_i) / r.
    const T half_L2 = 0.5 * dh * L * L, hLr = h * L * inv_r;
    dy[4] = T{};
    dy[5] = half_L2 * nx + hLr * (y[5] - np * nx);
    dy[6] = half_L2 * ny + hLr * (y[6] - np * ny);
    dy[7] = half_L2 * nz + hLr * (y[7] - np * nz);
  }

  Mat4 metric(const Vec4& x) const;
  Mat4 inverse_metric(const Vec4& x) const;
  Mat4Derivs metric_derivatives(const Vec4& x) const;
  // The static chart's metric at s = (t, r, θ, φ), for tests.
  Mat4 static_metric(const Vec4& s) const;

  // Scene (static) <-> trace (Kerr–Schild): t_KS = t + sense T(r) with
  // T' = h / F, x = r (sin θ cos φ, sin θ sin φ, cos θ); valid between the
  // horizons (T diverges on them).
  Vec4 trace_from_scene(const Vec4& s) const;
  Vec4 scene_from_trace(const Vec4& x) const;
  Vec4 scene_vector(const Vec4& x, const Vec4& v) const;
  Vec4 scene_time_gradient(const Vec4& x) const;
  // {∂_t, ∂_r, ∂_θ, ∂_φ / sin θ} of the static chart at the scene point s,
  // in trace components (finite on the axis: the limit at s's φ).
  std::array<Vec4, 4> polar_basis(const Vec4& s) const;
  // T(r): Σ_k A_k ln|r - r_k| - r over the roots r_k of r F(r) (r_b, r_c and
  // -(r_b + r_c)), A_k the residues of 1/F there; docs/physics.md.
  double time_function(double r) const;

 private:
  static double radius(const Vec4& x) { return std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]); }
  double M_, lambda_, lambda3_;
  double sense_;  // l_t: +1 ingoing, -1 outgoing
  double r_b_ = 0.0, r_c_ = 0.0, r_n_ = 0.0;  // the roots of r F(r)
  double residue_[3] = {0.0, 0.0, 0.0};        // of 1/F at r_b, r_c, r_n
  double r_capture_ = 0.0, r_stop_ = 0.0, r_stop2_ = 0.0, sky_lapse_ = 1.0;
};

}  // namespace lc
