#pragma once
// What every traversable wormhole here shares: a static, spherically
// symmetric throat joining two asymptotically flat universes, with no
// gravitational pull (Morris & Thorne, Am. J. Phys. 56, 395 (1988), their
// metric with the redshift function Φ = 0):
//   ds^2 = -dt^2 + dl^2 + r(l)^2 (dθ^2 + sin^2 θ dφ^2),
// l the proper radial distance from the throat (l > 0 this universe, l < 0
// the other), r(l) >= r(0) the circumference radius.  The Ellis wormhole
// (spacetime/ellis_wormhole.hpp) and the Interstellar one
// (spacetime/interstellar_wormhole.hpp) differ only in r(l): each writes
// shape<T>(l, r, dr/dl) and its photon region; the metric, Hamilton's
// equations, the charts, the two far ends and the skies' directions come
// from here.
//
// Scene chart: (t, l, θ, φ) — polar, with the signed l as its r, so a
// position {r = -10, ...} is 10 beyond the throat and a layer's hit.r is l.
// Trace chart: Cartesian x = R n(θ, φ) with l = R - c/R, c = s^2/4 (s the
// shape's chart scale, its throat radius): R runs over (0, ∞) as l over
// the reals, the throat is the sphere R = s/2, this universe's infinity
// R -> ∞ and the other's R -> 0, and the chart is regular everywhere
// between (no axis, no throat singularity).  dl/dR = 1 + c/R^2 >= 1, so
// light is no faster than 1 in these coordinates radially; across, its
// coordinate speed is R/r (<= 1 for Ellis, where the chart is isotropic).
// The inversion x -> -c x/|x|^2 swaps the universes (R -> c/R, l -> -l)
// and keeps orientation: the other universe's sky directions are read in
// it (escape_direction), so a ray straight through the throat keeps its
// direction and the other sky is not mirrored.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "core/constants.hpp"
#include "core/lanes.hpp"
#include "core/tensor.hpp"
#include "spacetime/ends.hpp"

namespace lc {

// S, the CRTP class, provides
//   template <class T> void shape(const T& l, T& r, T& dr) const:
//     r(l) and dr/dl, T double or lanes;
//   double chart_scale() const: s, its throat radius r(0).
template <class S>
struct MorrisThorne {
  // This universe's infinity (end 0, where the scene's `sky` is) and the
  // other's (a sky of its own: the scene's `skies.other_side`).
  static constexpr std::array ends = {SpacetimeEnd{"infinity", EndKind::infinity},
                                      SpacetimeEnd{"other_side", EndKind::infinity}};
  // The scene's r is l: <= 0 at and beyond the throat (spacetime/chart.hpp).
  static constexpr bool signed_radius = true;

  // l at trace-chart radius R, and R at l (exact to rounding on both sides:
  // the form without cancellation for each sign).
  double proper_distance(double R) const { return R - c() / R; }
  double chart_radius(double l) const {
    const double q = std::sqrt(l * l + 4.0 * c());
    return l >= 0.0 ? 0.5 * (l + q) : 2.0 * c() / (q - l);
  }

  // Hamilton's equations for H = 1/2 (-p_t^2 + u |p|^2 + w (n.p)^2), the
  // inverse spatial metric g^ij = u δ_ij + w n_i n_j with u = R^2/r^2 and
  // w = 1/Ω^2 - u (Ω = dl/dR), on y = (x^μ, p_μ), T double or lanes.  A
  // straight transcription of -∂H/∂x with ∂(n.p)/∂x = (p - (n.p) n)/R.
  template <class T>
  void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    const T R = sqrt_of(y[1] * y[1] + y[2] * y[2] + y[3] * y[3]);
    const T iR = 1.0 / R;
    const T nx = y[1] * iR, ny = y[2] * iR, nz = y[3] * iR;
    const T l = R - c() * iR;
    T r, dr;
    self().template shape<T>(l, r, dr);
    const T om = 1.0 + c() * iR * iR, d_om = -2.0 * c() * iR * iR * iR;
    const T ir = 1.0 / r;
    const T u = R * R * ir * ir;
    const T u_R = 2.0 * R * ir * ir * (1.0 - R * dr * om * ir);
    const T iom2 = 1.0 / (om * om);
    const T w = iom2 - u;
    const T w_R = -2.0 * d_om * iom2 / om - u_R;
    const T q = nx * y[5] + ny * y[6] + nz * y[7];
    const T p2 = y[5] * y[5] + y[6] * y[6] + y[7] * y[7];
    const T wq = w * q;
    dy[0] = -y[4];
    dy[1] = u * y[5] + wq * nx;
    dy[2] = u * y[6] + wq * ny;
    dy[3] = u * y[7] + wq * nz;
    const T radial = -(0.5 * (u_R * p2 + w_R * q * q) - wq * q * iR);
    const T along_p = -wq * iR;
    dy[4] = T{};
    dy[5] = radial * nx + along_p * y[5];
    dy[6] = radial * ny + along_p * y[6];
    dy[7] = radial * nz + along_p * y[7];
  }

  // Out of line (spacetime/morris_thorne_impl.hpp, instantiated in each S's
  // .cpp).
  Mat4 metric(const Vec4& x) const;
  Mat4 inverse_metric(const Vec4& x) const;
  Mat4Derivs metric_derivatives(const Vec4& x) const;

  // No pull: a body at rest stays at rest, and nothing is seen as a mass
  // from far away (the lensing is the space's shape alone).
  double asymptotic_mass() const { return 0.0; }
  double far_field_radius() const { return std::numeric_limits<double>::infinity(); }

  // The far-end rule in |l|: end 0 beyond the escape radius with l growing,
  // end 1 beyond it with l falling.
  template <class Y, class D>
  Flight flight(const Y& y, const D& dy, const FlightRadii& radii) const {
    const double R = std::sqrt(y(1) * y(1) + y(2) * y(2) + y(3) * y(3));
    const double l = R - c() / R, l2 = l * l;
    if (!(l2 > radii.free2) && !(l2 > radii.escape2)) return {};  // the slope is not read
    const double x_dx = y(1) * dy(1) + y(2) * dy(2) + y(3) * dy(3);
    const bool away = l > 0.0 ? x_dx > 0.0 : x_dx < 0.0;
    return {l2 > radii.free2 && away, l2 > radii.escape2 && away, static_cast<std::uint8_t>(l > 0.0 ? 0 : 1)};
  }
  // Both universes are flat far out, with g_tt = -1 everywhere.
  static double sky_source_lapse(std::size_t) { return 1.0; }
  // |l| over the shell lo <= R <= hi: at one of its edges (l grows with R),
  // without bound where the shell reaches R = 0, the other infinity.
  double flight_reach(double lo, double hi) const {
    if (!(lo > 0.0)) return std::numeric_limits<double>::infinity();
    return std::max(std::abs(proper_distance(lo)), std::abs(proper_distance(hi)));
  }
  // The sky's direction of a ray leaving x along d: d itself in this
  // universe; in the other, d carried by the inversion x -> -c x/|x|^2
  // (its differential, up to scale: d reflected in the plane normal to x,
  // then reversed).  The bending still to come beyond the escape radius
  // (~ s^2/l^2 for Ellis) is neglected.
  Vec3 escape_direction(const Vec4& x, const Vec3& d) const {
    const double R2 = x[1] * x[1] + x[2] * x[2] + x[3] * x[3];
    if (R2 >= c()) return d;
    const double xd = (x[1] * d[0] + x[2] * d[1] + x[3] * d[2]) / R2;
    return {2.0 * xd * x[1] - d[0], 2.0 * xd * x[2] - d[1], 2.0 * xd * x[3] - d[2]};
  }

  // No horizon: no ray is captured, and an observer may stand anywhere
  // (the scene's l is any real number; there is no inside of the throat).
  bool captured(const Vec4&) const { return false; }
  double capture_margin(const Vec4&) const { return 1.0; }
  bool inside_horizon(const Vec4&) const { return false; }
  std::string_view why_no_observer(const Vec4&) const { return {}; }

  // Scene (t, l, θ, φ) <-> trace (t, x, y, z).
  Vec4 trace_from_scene(const Vec4& s) const {
    const double R = chart_radius(s[1]), sn = std::sin(s[2]);
    return {s[0], R * sn * std::cos(s[3]), R * sn * std::sin(s[3]), R * std::cos(s[2])};
  }
  Vec4 scene_from_trace(const Vec4& x) const;
  Vec4 scene_vector(const Vec4& x, const Vec4& v) const;
  static Vec4 scene_time_gradient(const Vec4&) { return {1.0, 0.0, 0.0, 0.0}; }
  // {∂_t, ∂_l, ∂_θ, ∂_φ / sin θ} at the scene point s, in trace components:
  // ∂_l = n / Ω; finite on the axis (the limit at s's φ).
  std::array<Vec4, 4> polar_basis(const Vec4& s) const;

 private:
  double c() const { return 0.25 * self().chart_scale() * self().chart_scale(); }
  const S& self() const { return static_cast<const S&>(*this); }
};

}  // namespace lc
