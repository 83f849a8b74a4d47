#pragma once
// What every Majumdar–Papapetrou spacetime shares: extreme
// Reissner–Nordström holes of charge equal to their mass, at rest because
// their electric repulsion balances their pull, in isotropic Cartesian
// coordinates ds^2 = -U^-2 dt^2 + U^2 (dx^2 + dy^2 + dz^2) with
// U = 1 + Σ m_i / |x - x_i| (Majumdar 1947, Papapetrou 1947; Hartle &
// Hawking, Commun. Math. Phys. 26, 87 (1972) for the holes).  The dihole
// (two holes on the z axis, the paper's) and lc.majumdar_papapetrou (any
// number anywhere) differ only in U: each writes potential_with_gradient<T>()
// and asymptotic_mass(); the metric, Hamilton's equations, the
// capture rule, the far-field escape and the disk's circular orbits come
// from here.  The horizons are the coordinate points x_i; rays are stopped
// where U exceeds extreme_hole_capture_potential (core/constants.hpp).

#include "core/constants.hpp"
#include "core/lanes.hpp"
#include "core/tensor.hpp"
#include "spacetime/weak_field_tail.hpp"

namespace lc {

// S, the CRTP class, provides
//   template <class T> [[gnu::always_inline]] T potential_with_gradient(X, Y,
//     Z, gx, gy, gz):
//     U at the spatial point (X, Y, Z) and its gradient, T double or lanes;
//   asymptotic_mass(): Σ m_i.
template <class S>
struct ExtremeHoles {
  // U and (where grad is given) its gradient at the event x.
  double potential(const Vec4& x, Vec3* grad = nullptr) const {
    Vec3 g;
    const double U = self().template potential_with_gradient<double>(x[1], x[2], x[3], g[0], g[1], g[2]);
    if (grad) *grad = g;
    return U;
  }

  // Hamilton's equations for H = 1/2 (-U^2 p_t^2 + U^-2 |p|^2) on the state
  // y = (x^mu, p_mu).  T is double or a vector of lanes (core/lanes.hpp),
  // one ray each.  Always inlined into the integrator's stages, and S's
  // potential_with_gradient() into it: the compiler's own choice there changes with
  // unrelated code elsewhere in the renderer (docs/performance.md, change
  // 32).
  template <class T>
  [[gnu::always_inline]] void rhs(const std::array<T, 8>& y, std::array<T, 8>& dy) const {
    T gx, gy, gz;
    const T U = self().template potential_with_gradient<T>(y[1], y[2], y[3], gx, gy, gz);
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

  bool captured(const Vec4& x) const { return potential(x) > extreme_hole_capture_potential; }
  // A smooth function negative exactly where captured() holds (see Kerr).
  double capture_margin(const Vec4& x) const { return extreme_hole_capture_potential - potential(x); }
  bool inside_horizon(const Vec4& x) const { return captured(x); }

  // The far field is the monopole Σ m_i in isotropic coordinates
  // (weak_field_tail.hpp); S's far_field_radius() says where its other
  // multipoles bend light by less than far_field_bending.
  Vec3 escape_direction(const Vec4& x, const Vec3& d) const {
    return isotropic_escape_direction({x[1], x[2], x[3]}, d, self().asymptotic_mass());
  }

  // The metric's diagonal (it has nothing else): -U^-2, U^2, U^2, U^2.
  Vec4 diagonal_metric(const Vec4& x) const {
    const double U = potential(x), U2 = U * U;
    return {-1.0 / U2, U2, U2, U2};
  }
  // Out of line (spacetime/extreme_holes_impl.hpp, instantiated in each
  // S's .cpp): the renderer's callers get the same code whatever inlines.
  Mat4 metric(const Vec4& x) const;
  Mat4 inverse_metric(const Vec4& x) const;
  Mat4Derivs metric_derivatives(const Vec4& x) const;

  // Thin-disk matter at the trace event x (docs/light.md): on the circular
  // orbit about the z axis that the radial pull at x allows, anticlockwise
  // seen from +z, at x's cylindrical radius R: Omega^2 = -∂_R g_tt / ∂_R
  // g_phiphi with g_tt = -U^-2, g_phiphi = U^2 R^2 (a geodesic in the plane
  // z = 0 of holes placed symmetrically about it and about the axis; for
  // others the pull along z and about the axis is ignored).  At rest where no
  // such orbit exists (it would be faster than light, or the pull points
  // outwards) and on the axis.
  Vec4 disk_velocity(const Vec4& x) const;

 private:
  const S& self() const { return static_cast<const S&>(*this); }
};

}  // namespace lc
