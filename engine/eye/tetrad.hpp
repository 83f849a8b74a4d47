#pragma once
// Orthonormal local tetrads e_a^mu (a = 0 time leg, 1..3 spatial legs) in
// trace coordinates, and the standard observers' frames.  Legs of the polar
// frames are ordered (e_t, e_r, e_theta, e_phi); a camera "looking at the hole"
// uses forward = -e_r, up = -e_theta, right = e_phi (docs/architecture.md, "Conventions").

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/tensor.hpp"
#include "spacetime/chart.hpp"

namespace lc {

struct Tetrad {
  std::array<Vec4, 4> e;  // e[a][mu]
};

class ObserverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Gram–Schmidt in the metric g: the first vector must be timelike, the rest
// are made orthonormal to it and each other in order.  Throws ObserverError
// (naming `who`) when the first vector is not timelike or the set degenerates.
Tetrad orthonormalize(const Mat4& g, const std::array<Vec4, 4>& basis, const char* who);

// Frame of an observer with 4-velocity u (normalised, future-directed) made
// by a pure Lorentz boost of `rest` (whose time leg need not be u): spatial
// directions are not rotated relative to `rest`.  v are the components of the
// 3-velocity in units of c along rest's spatial legs.
Tetrad boost(const Tetrad& rest, const Vec3& v);

// How f's rest space (the span of its legs e1..e3) lies in coordinates, per
// unit of proper length: `stretch`, the longest spatial coordinate length
// of a unit rest-space vector once slid along e0 to e0's own coordinate
// time (the vector d - (d^t / e0^t) e0: where a point of f's rest space
// lies relative to where f's origin is at that point's time, for an origin
// moving along e0); `tilt`, the largest |d^t| of a unit rest-space vector
// (how far in coordinate time the rest space leans).  Exact: the largest
// singular value of the 3x3 map, by the closed form for a symmetric 3x3
// eigenvalue (O. K. Smith, Comm. ACM 4 (1961) 168).
struct RestSpaceSpan {
  double stretch, tilt;
};
RestSpaceSpan rest_space_span(const Tetrad& f);

// Components of the 3-velocity of u relative to frame f (|v| < 1).
Vec3 relative_velocity(const Mat4& g, const Tetrad& f, const Vec4& u);

// Static observer at a scene point: time leg along ∂_t; spatial legs from the
// polar basis {∂_r, ∂_theta, ∂_phi/sin(theta)} (regular on the axis).  Throws
// where the spacetime says no observer may stand (S::why_no_observer:
// inside a horizon) or where ∂_t is not timelike (Kerr ergoregion).
template <class S>
Tetrad static_polar_tetrad(const S& st, const Vec4& scene_point) {
  const Vec4 x = st.trace_from_scene(scene_point);
  if (const std::string_view why = st.why_no_observer(x); !why.empty())
    throw ObserverError(fmt::format("static observer: the position is {}", why));
  const Mat4 g = st.metric(x);
  if (g[0][0] >= 0.0)
    throw ObserverError("static observer: no static observer exists here (inside the ergoregion, g_tt >= 0)");
  return orthonormalize(g, st.polar_basis(scene_point), "static observer");
}

// The zero-angular-momentum observer's 4-velocity at the trace event x,
// outside any horizon: along -grad t (scene time), normalised, so it exists
// everywhere outside the horizon, ergoregion included; in a static
// spacetime it is the static observer.
template <class S>
Vec4 zamo_velocity(const S& st, const Vec4& x) {
  const Mat4 gi = st.inverse_metric(x);
  const Vec4 dt = st.scene_time_gradient(x);
  Vec4 u{};
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) u[m] -= gi[m][n] * dt[n];
  // u.u = g^{mn} t_m t_n = -u^m t_m
  const double norm = std::sqrt(u[0] * dt[0] + u[1] * dt[1] + u[2] * dt[2] + u[3] * dt[3]);
  for (double& c : u) c /= norm;
  return u;
}

// Zero-angular-momentum observer's frame (zamo_velocity).
template <class S>
Tetrad zamo_polar_tetrad(const S& st, const Vec4& scene_point) {
  const Vec4 x = st.trace_from_scene(scene_point);
  if (const std::string_view why = st.why_no_observer(x); !why.empty())
    throw ObserverError(fmt::format("ZAMO: the position is {}", why));
  auto basis = st.polar_basis(scene_point);
  basis[0] = zamo_velocity(st, x);
  return orthonormalize(st.metric(x), basis, "ZAMO");
}

// Frame of an observer with the given unit future-directed 4-velocity u (trace
// coordinates) at a scene point: the static polar frame boosted to u.
template <class S>
Tetrad tetrad_from_velocity(const S& st, const Vec4& scene_point, const Vec4& u) {
  const Tetrad rest = static_polar_tetrad(st, scene_point);
  return boost(rest, relative_velocity(st.metric(st.trace_from_scene(scene_point)), rest, u));
}

// Static observer of a Cartesian scene with legs (e_t, e_x, e_y, e_z).
template <class S>
Tetrad static_cartesian_tetrad(const S& st, const Vec4& x) {
  if (const std::string_view why = st.why_no_observer(x); !why.empty())
    throw ObserverError(fmt::format("static observer: the position is {}", why));
  return orthonormalize(st.metric(x), {Vec4{1, 0, 0, 0}, Vec4{0, 1, 0, 0}, Vec4{0, 0, 1, 0}, Vec4{0, 0, 0, 1}},
                        "static observer");
}

// The static frame whose legs a scene's directions and velocities refer to
// (a sphere at rest, a worldline's start, a geodesic spec's start): the
// polar one (e_r, e_theta, e_phi) in a polar chart, else the Cartesian one
// (e_x, e_y, e_z).  At a scene point.
template <class S>
Tetrad static_frame(const S& st, const Vec4& scene_point) {
  if constexpr (S::chart == SceneChart::polar)
    return static_polar_tetrad(st, scene_point);
  else
    return static_cartesian_tetrad(st, st.trace_from_scene(scene_point));
}

// The frame a moving body's velocity is given relative to at a scene point
// (a worldline's start, a geodesic spec's): the static frame where a static
// observer exists, else (inside a Kerr ergoregion, where none can stand) the
// ZAMO's, with the same polar legs.  So a fall may start anywhere outside
// the horizon.  Throws ObserverError inside a horizon.
template <class S>
Tetrad velocity_reference_frame(const S& st, const Vec4& scene_point) {
  if constexpr (S::chart == SceneChart::polar) {
    const Vec4 x = st.trace_from_scene(scene_point);
    if (!st.inside_horizon(x) && st.metric(x)[0][0] >= 0.0) return zamo_polar_tetrad(st, scene_point);
  }
  return static_frame(st, scene_point);
}

}  // namespace lc
