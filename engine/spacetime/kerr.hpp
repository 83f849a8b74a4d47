#pragma once
// Kerr–Newman spacetime (mass M >= 0, spin a, charge Q, a^2 + Q^2 <= M^2;
// Kerr at Q = 0, Reissner–Nordström at a = 0) in ingoing Cartesian
// Kerr–Schild coordinates (t, x, y, z): regular on the spin axis and across the
// future horizon.  Geometric units with 4 pi epsilon_0 = 1 (Q in units of M).
// g_{mu nu} = eta_{mu nu} + f l_mu l_nu with
//   f = (2 M r - Q^2) r^2 / (r^4 + a^2 z^2),
//   l = (1, (r x + a y)/(r^2 + a^2), (r y - a x)/(r^2 + a^2), z / r),
// and r the Boyer–Lindquist radius, the root of
//   (x^2 + y^2)/(r^2 + a^2) + z^2/r^2 = 1.
// Relation to Boyer–Lindquist (t, r, theta, phi), e.g. Visser, "The Kerr
// spacetime: a brief introduction", arXiv:0706.0622, sec. 3 (sec. 6 for the
// charge):
//   x + i y = (r + i a) sin(theta) e^{i phit},  z = r cos(theta),
//   t_KS = t_BL + T(r),  phit = phi + Phi(r),  T' = (2 M r - Q^2) / Delta,
//   Phi' = a / Delta,  Delta = r^2 - 2 M r + a^2 + Q^2.
// Scene coordinates (what users and data layers see) are Boyer–Lindquist.
//
// The charge is a field of this class, not a spacetime of its own: every
// formula is Kerr's with 2 M r -> 2 M r - Q^2 (and Delta with it), the
// fast path's separation survives it (Carter's constant), and at Q = 0 the
// arithmetic is Kerr's to the bit (the Q terms add exact zeros), so Kerr
// frames keep their bytes.  Light carries no charge, and the disk's matter
// and the spheres are taken as neutral: they move on geodesics.
//
// The outgoing variant is the time reverse: t_KS = t_BL - T(r),
// phit = phi - Phi(r), x + i y = (r - i a) sin(theta) e^{i phit} and
// l = (-1, (r x - a y)/(r^2 + a^2), (r y + a x)/(r^2 + a^2), z / r), i.e. the
// ingoing form with a -> -a and l_t -> -1.  It is regular across the past
// horizon, where rays traced backwards in time from a camera go: in ingoing
// coordinates those rays wind round the horizon without reaching it (phit and
// t diverge logarithmically) and cost many steps.  Future-directed curves use
// the ingoing form for the same reason.

#include <cmath>

#include "core/fields.hpp"
#include "core/lanes.hpp"
#include "core/tensor.hpp"
#include "light/novikov_thorne.hpp"
#include "spacetime/model.hpp"

namespace lc {

enum class KerrSchildSense { ingoing, outgoing };

// T(r) = ∫ (2 M r - Q^2) / Delta dr (zero for M = 0): the time a radial
// principal null ray gains on flat space, so that r + T(r) is the tortoise
// radius r*, dr*/dr = (r^2 + a^2) / Delta.  Integration constants in
// docs/physics.md.
double kerr_radial_time(double M, double a, double Q, double r);

class Kerr : public HamiltonianFromRhs<Kerr>, public CartesianInfinity, public ObserversOutsideHorizons<Kerr> {
 public:
  static constexpr std::string_view name = "kerr";
  static constexpr SceneChart chart = SceneChart::polar;  // Boyer–Lindquist
  // The metric does not depend on t (in either chart): frames that differ
  // only by the observer's time may share rays (scene/still_key.hpp).
  static constexpr bool stationary = true;
  // Infinity, reached in the Kerr–Schild trace chart by its Cartesian
  // radius (and on the fast path where u = 1/r reaches 0), and the outer
  // horizon (for M = 0 no ray reaches it).
  static constexpr std::array ends = {SpacetimeEnd{"infinity", EndKind::infinity},
                                      SpacetimeEnd{"horizon", EndKind::horizon}};
  static constexpr std::array other_names = {
      OtherName{"kerr_newman", "lc.kerr{mass = M, spin = a, charge = Q}"},
      OtherName{"reissner_nordstrom", "lc.kerr{mass = M, charge = Q}"},
      OtherName{"schwarzschild", "lc.kerr{mass = M}"}};
  struct Params {
    double mass = 0.0, spin = 0.0, charge = 0.0;
    static constexpr auto fields = std::tuple{
        field("mass", &Params::mass, std::optional<double>{}, at_least(0.0), std::nullopt, "the mass M"),
        field("spin", &Params::spin, std::optional<double>{0.0}, std::nullopt, std::nullopt,
              "the spin a = J/M, |a| <= M; a > 0 turns towards +phi"),
        quiet_at_default(field("charge", &Params::charge, std::optional<double>{0.0}, std::nullopt, std::nullopt,
                               "the electric charge Q (Kerr–Newman; Reissner–Nordström at spin 0), "
                               "a^2 + Q^2 <= M^2; its sign does not change the picture",
                               "M")),
    };
  };
  // Throws std::invalid_argument when M < 0, a^2 + Q^2 > M^2 or any is not
  // finite.
  Kerr(double mass, double spin, double charge, KerrSchildSense sense = KerrSchildSense::outgoing);
  Kerr(double mass, double spin, KerrSchildSense sense = KerrSchildSense::outgoing) : Kerr(mass, spin, 0.0, sense) {}
  explicit Kerr(const Params& p) : Kerr(p.mass, p.spin, p.charge) {}
  Params params() const { return {M_, a_, Q_}; }
  // In the outgoing chart (regular on the past horizon) for curves traced
  // into the past, the ingoing one for the future.
  Kerr for_tracing(TimeDirection d) const {
    return with_sense(d == TimeDirection::future ? KerrSchildSense::ingoing : KerrSchildSense::outgoing);
  }
  static std::vector<SpacetimeExample<Kerr>> examples() {
    std::vector<SpacetimeExample<Kerr>> out;
    for (auto sense : {KerrSchildSense::ingoing, KerrSchildSense::outgoing}) {
      for (double a : {0.0, 0.6, -0.9, 1.0}) out.push_back({Kerr(1.0, a, sense), 2.1, 40.0});
      for (auto [a, q] : {std::pair{0.0, 0.8}, {0.5, -0.6}, {-0.6, 0.8}}) out.push_back({Kerr(1.0, a, q, sense), 2.1, 40.0});
    }
    return out;
  }

  KerrSchildSense sense() const { return sense_ == 1.0 ? KerrSchildSense::ingoing : KerrSchildSense::outgoing; }
  // The same spacetime in the other Kerr–Schild chart.
  Kerr with_sense(KerrSchildSense s) const { return Kerr(M_, a_, Q_, s); }

  double mass() const { return M_; }
  // Mass seen from far away (for the weak-field tail of escaping rays).
  double asymptotic_mass() const { return M_; }
  double spin() const { return a_; }
  double charge() const { return Q_; }
  // Outer horizon r_+ = M + sqrt(M^2 - a^2 - Q^2) (0 for M = 0), and the
  // inner one r_-.
  double horizon_radius() const { return r_plus_; }
  double inner_horizon_radius() const { return r_minus_; }
  // Boyer–Lindquist radius of the circular equatorial photon orbit turning
  // with the hole (prograde) or against it (retrograde); 0 where M = 0.
  double photon_orbit_radius(bool prograde) const;
  // Boyer–Lindquist radius below which rays are taken as captured.
  double capture_radius() const { return r_capture_; }
  // Photon orbits lie within r <= 4M (the retrograde one's largest radius
  // at |a| = M; a charge pulls them in); in Kerr–Schild's Cartesian radius,
  // sqrt(r^2 + a^2 sin^2) at most, within 4M + |a|.
  double photon_reach() const { return 4.0 * M_ + std::abs(a_); }
  // No far-field shortcut: rays are integrated out to the escape radius.
  double far_field_radius() const { return std::numeric_limits<double>::infinity(); }
  Vec3 escape_direction(const Vec4& x, const Vec3& d) const { return first_order_escape_direction(x, d, M_); }

  // Boyer–Lindquist radius of a Kerr–Schild point.
  double bl_radius(double x, double y, double z) const {
    const double a2 = a_ * a_;
    const double w = x * x + y * y + z * z - a2;
    const double r2 = 0.5 * (w + std::sqrt(w * w + 4.0 * a2 * z * z));
    return std::sqrt(r2);
  }

  // Hamilton's equations for H = 1/2 g^{mu nu} p_mu p_nu on the state
  // y = (x^mu, p_mu): outputs dx^mu/dlambda = g^{mu nu} p_nu and dp_mu/dlambda
  // = -dH/dx^mu.  The hot path of every Kerr ray; uses g^{mu nu} = eta^{mu nu}
  // - f l^mu l^nu, so H needs only f, l and their gradients.  T is double or
  // a vector of lanes (core/lanes.hpp), one ray each.  Assumes the point is
  // off the ring singularity.
  template <class T>
  void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    const T X = y[1], Y = y[2], Z = y[3];
    const double a = ak_, a2 = a_ * a_;
    const T w = X * X + Y * Y + Z * Z - a2;
    const T r = sqrt_of(0.5 * (w + sqrt_of(w * w + 4.0 * a2 * Z * Z)));  // bl_radius
    const T r2 = r * r;
    const T inv_r = 1.0 / r;
    const T q = 1.0 / (r2 + a2);
    const T den = 1.0 / (r2 * r2 + a2 * Z * Z);
    // f's numerator (2 M r - Q^2) r^2, and f; at Q = 0 the charge's terms
    // are exact zeros (class comment).
    const T n = 2.0 * M_ * r2 * r - Q2_ * r2;
    const T f = n * den;
    const T lx = (r * X + a * Y) * q, ly = (r * Y - a * X) * q, lz = Z * inv_r;
    // L = l^mu p_mu with l^mu = (-l_t, lx, ly, lz), l_t = +1 ingoing, -1 outgoing.
    const T L = -sense_ * y[4] + lx * y[5] + ly * y[6] + lz * y[7];
    dy[0] = -y[4] + sense_ * f * L;
    dy[1] = y[5] - f * L * lx;
    dy[2] = y[6] - f * L * ly;
    dy[3] = y[7] - f * L * lz;
    // Gradient of r (implicit differentiation of the defining quartic).
    const T r3den = r2 * r * den;
    const T drx = X * r3den, dry = Y * r3den, drz = Z * (r2 + a2) * r * den;
    // f(r, z): partial derivatives, then chain rule.
    const T dfdr =
        (2.0 * M_ * r2 * (3.0 * a2 * Z * Z - r2 * r2) + 2.0 * Q2_ * r * (r2 * r2 - a2 * Z * Z)) * den * den;
    const T dfz_r = -2.0 * n * a2 * Z * den * den;
    // dL/dx^j = sum_i (d l_i/dx^j) p_i = (dr/dx^j) A + B_j, where A collects
    // every term through r and B_j the explicit x, y, z dependence of l.
    const T A = q * (X * y[5] + Y * y[6]) - 2.0 * r * q * (lx * y[5] + ly * y[6]) - lz * inv_r * y[7];
    const T Bx = q * (r * y[5] - a * y[6]), By = q * (r * y[6] + a * y[5]), Bz = y[7] * inv_r;
    const T half_L2 = 0.5 * L * L, fL = f * L;
    dy[4] = T{};
    dy[5] = dfdr * drx * half_L2 + fL * (drx * A + Bx);
    dy[6] = dfdr * dry * half_L2 + fL * (dry * A + By);
    dy[7] = (dfdr * drz + dfz_r) * half_L2 + fL * (drz * A + Bz);
  }

  // Captured: inside the capture radius (see constants.hpp).  Kerr–Schild point.
  bool captured(const Vec4& x) const { return M_ > 0.0 && bl_radius(x[1], x[2], x[3]) < r_capture_; }
  // A smooth function negative exactly where captured() holds, to locate
  // where a ray crossed into the capture region within a step.
  double capture_margin(const Vec4& x) const { return M_ > 0.0 ? bl_radius(x[1], x[2], x[3]) - r_capture_ : 1.0; }
  // Inside (or on) the outer horizon.
  bool inside_horizon(const Vec4& x) const { return M_ > 0.0 && bl_radius(x[1], x[2], x[3]) <= r_plus_; }

  Mat4 metric(const Vec4& x) const;
  Mat4 inverse_metric(const Vec4& x) const;
  // d[alpha][mu][nu] = ∂_alpha g_{mu nu}, analytic.
  Mat4Derivs metric_derivatives(const Vec4& x) const;

  // Boyer–Lindquist metric at BL coordinates (t, r, theta, phi); for tests and
  // documentation of conventions (g_{t phi} = -(2 M r - Q^2) a sin^2 / Sigma).
  Mat4 bl_metric(const Vec4& s) const;

  // Thin-disk matter in the equatorial plane (docs/light.md): on circular
  // Keplerian orbits co-rotating with the hole (a = 0: anticlockwise seen
  // from +z) at and outside the ISCO; inside it plunging with the ISCO orbit's
  // energy and angular momentum (Cunningham 1975, ApJ 202, 788); at rest
  // where M = 0.  u^mu in Boyer–Lindquist at radius r (outside the horizon),
  // and in the trace chart at the trace event x.
  Vec4 disk_velocity_bl(double r) const;
  Vec4 disk_velocity(const Vec4& x) const;
  // The Novikov–Thorne flux of its disk: for M > 0 and a^2 + Q^2 < M^2
  // (Page & Thorne's closed form at Q = 0, their integral with a charge).
  std::optional<NovikovThorneFlux> thin_disk_flux() const {
    if (M_ > 0.0 && a_ * a_ + Q_ * Q_ < M_ * M_) return NovikovThorneFlux(M_, a_, Q_);
    return std::nullopt;
  }
  // Radius of the innermost stable circular orbit co-rotating with the hole
  // (core/kerr_isco.hpp); 0 where M = 0.
  double isco_radius() const { return r_isco_; }

  // Coordinate maps between scene (Boyer–Lindquist) and trace (Kerr–Schild)
  // coordinates; valid outside the horizon (T and Phi diverge on it).
  Vec4 trace_from_scene(const Vec4& s) const;
  Vec4 scene_from_trace(const Vec4& x) const;
  // J[mu][nu] = ∂x_KS^mu / ∂s_BL^nu at the BL point s.
  Mat4 trace_jacobian(const Vec4& s) const;
  // Components in BL of a vector given in KS at the KS point x.
  Vec4 scene_vector(const Vec4& x, const Vec4& v) const;
  // Gradient (covector, KS components) of BL time t at the KS point x.
  Vec4 scene_time_gradient(const Vec4& x) const;

  // The BL coordinate basis at a KS point x as KS vectors, with the phi vector
  // divided by sin(theta): {∂_t, ∂_r, ∂_theta, ∂_phi / sin(theta)}.  Every one is
  // finite on the spin axis, where the last two are the limit at the given phi
  // (theta = 0 alone does not fix phi, so it is passed in scene form).
  std::array<Vec4, 4> polar_basis(const Vec4& scene_point) const;

  // BL -> KS shifts of t and phi in this chart: t_KS = t_BL + time_shift(r),
  // phit = phi + phi_shift(r) (sense * T(r) and sense * Phi(r); integration
  // constants documented in docs/physics.md).
  double time_shift(double r) const;
  double phi_shift(double r) const;

 private:
  double M_, a_, Q_;
  double Q2_;     // Q^2
  double sense_;  // l_t: +1 ingoing, -1 outgoing
  double ak_;     // spin as it enters the chart's formulas: sense * a
  double r_plus_ = 0.0, r_minus_ = 0.0, r_capture_ = 0.0, r_isco_ = 0.0;
};

}  // namespace lc
