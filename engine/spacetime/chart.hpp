#pragma once
// What a spacetime's scene coordinates are — the coordinates shots, data
// layers and reports use — and the event of a trace-coordinate point in
// them.  Each spacetime declares its chart (S::chart); code that differs by
// chart asks that, never which spacetime it is.

#include <cmath>

#include "core/constants.hpp"
#include "core/tensor.hpp"

namespace lc {

enum class SceneChart {
  polar,      // (t, r, theta, phi) like Boyer–Lindquist: positions {r, theta, phi} in degrees
  cartesian,  // (t, x, y, z): positions {x, y, z}
};

// Whether the polar scene chart's r of S is signed, a place on either side
// of 0 (a wormhole's proper distance l from its throat: S::signed_radius),
// rather than a radius > 0.
template <class S>
constexpr bool scene_radius_is_signed() {
  if constexpr (requires { S::signed_radius; })
    return S::signed_radius;
  else
    return false;
}

// The rates dθ and dφ of a spatial vector v (components 1-3) at the
// Cartesian-like point x (components 1-3) of radius r = |x|, for the polar
// angles about the origin: dθ = (cos θ dρ - sin θ dz) / r,
// dφ = (x dy - y dx) / ρ^2 (ρ the cylindrical radius).  On the axis dθ is
// the rate of leaving it and dφ = 0 (as Kerr's chart maps do).  For the
// scene_vector of charts whose spheres are those of the trace chart
// (Kottler, the wormholes).
inline void polar_angle_rates(const Vec4& x, const Vec4& v, double r, double& dth, double& dphi) {
  const double rho = std::hypot(x[1], x[2]);
  dphi = 0.0;
  if (rho > 1e-9 * r) {
    const double drho = (x[1] * v[1] + x[2] * v[2]) / rho;
    dth = (x[3] / r * drho - rho / r * v[3]) / r;
    dphi = (x[1] * v[2] - x[2] * v[1]) / (rho * rho);
  } else {
    dth = std::hypot(v[1], v[2]) / r;
  }
}

// Which way in time curves are traced (a chart may be chosen to be regular
// where they go: Kerr::for_tracing).
enum class TimeDirection { future, past };

// Scene time, radius and longitude of a trace-coordinate event: the chart's
// own t, r and phi where it is polar, else t and the spherical r and phi
// about the origin; phi in [0, 2 pi).
template <class S>
inline void scene_polar(const S& st, const Vec4& x, double& t, double& r, double& phi) {
  if constexpr (S::chart == SceneChart::polar) {
    const Vec4 s = st.scene_from_trace(x);
    t = s[0];
    r = s[1];
    phi = s[3];
  } else {
    t = st.scene_from_trace(x)[0];
    r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    phi = std::atan2(x[2], x[1]);
    if (phi < 0) phi += two_pi;
  }
}

}  // namespace lc
