#pragma once
// Whether and where a ray step meets a sphere riding its worldline (the
// paper's spacetime tube): the simultaneity of a ray point with the
// sphere's centre and the sampling of |xi|^2 - R^2 along the steps that
// the cheap box tests of objects/bounded_body.hpp let through.  For objects/sphere.hpp.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include "geodesic/crossing.hpp"
#include "geodesic/ray_loop.hpp"
#include "objects/bounded_body.hpp"
#include "objects/sphere_body.hpp"
#include "objects/step_query.hpp"

namespace lc::detail {

// The metric at one event, for the sphere test's many inner products: just
// its diagonal where the chart has nothing else (the dihole, flat space),
// else the whole matrix.
template <class S>
struct MetricAt {
  static constexpr bool diagonal = requires(const S& s, const Vec4& x) { s.diagonal_metric(x); };
  std::conditional_t<diagonal, Vec4, Mat4> g{};

  MetricAt() = default;
  MetricAt(const S& st, const Vec4& x) {
    if constexpr (diagonal)
      g = st.diagonal_metric(x);
    else
      g = st.metric(x);
  }
  // g(a, b).
  double operator()(const Vec4& a, const Vec4& b) const {
    if constexpr (diagonal)
      return g[0] * a[0] * b[0] + g[1] * a[1] * b[1] + g[2] * a[2] * b[2] + g[3] * a[3] * b[3];
    else
      return contract(g, a, b);
  }
};

// The coordinate time t of the sphere's event C(t) simultaneous with the ray
// point X: the root of lag(t) = g(X - C(t), u(t)), the local linearisation
// of docs/architecture.md (X on the rest frame's slice through C).  Starts from t_start
// (X's own time, or the answer for a nearby point) and returns C, u and, in
// g, the metric at C (the caller's distance needs it).
//
// d(lag)/dtau = -g(u, u) = 1 to first order, so the first (Newton) step
// moves tau by -lag: exact in flat space.  That slope ignores the metric's
// change and the sphere's acceleration, ~20% off near the dihole's holes,
// so from the second step on the secant slope takes over (superlinear).
// To 1e-8 in proper time near the sphere in at most six steps, from the
// given start and, if that does not settle, again from X's own time; beyond
// 1.5 R it stops once the centre is known to 10% of the room to spare, all
// sphere tracing needs.  (Newton with the exact slope, from the metric's rate and
// du/dt, converges in fewer steps but costs more per frame: docs/performance.md,
// "Measured and rejected".)  *settled, where given, says whether the
// answer is a root: near a sphere whose centre swings through a strong field
// (the dihole's), lag(t) may have no root near X's own time at all, and the
// search then ends wherever its last step took it.
template <class S>
double sphere_simultaneous_time(const S& st, const SphereBody& sphere, const Vec4& X, double t_start, Vec4& C, Vec4& u,
                                MetricAt<S>& g, bool* settled = nullptr) {
  const double R = sphere.radius;
  // To 1e-8 in proper time (the centre moves by less than that) near the
  // sphere; farther out sphere tracing only needs |xi| to a fraction of the
  // distance to spare: 10% of the coordinate distance beyond 1.5 R, judged
  // from the latest centre (a search that starts far from its root may end
  // near the sphere).  |xi|, the part of X - C orthogonal to u, does not
  // change to first order as C slides along u, so an unfinished lag moves it
  // far less than |lag|.  (Why 10%: docs/performance.md, change 26.)
  auto tolerance_at = [&](const Vec4& centre) {
    double dx2 = 0.0;
    for (int k = 1; k < 4; ++k) dx2 += (X[k] - centre[k]) * (X[k] - centre[k]);
    return 1e-8 + (dx2 > 2.25 * R * R ? 0.1 * (std::sqrt(dx2) - 1.5 * R) : 0.0);
  };
  double t = t_start;
  for (int attempt = 0;; ++attempt) {
    sphere.centre(t, C, u);
    g = MetricAt<S>(st, C);
    double lag = g(X - C, u);
    double tolerance = tolerance_at(C);
    double t_prev = t, lag_prev = lag;
    for (int it = 0; it < 6 && std::abs(lag) >= tolerance; ++it) {
      double next = C[0] - lag * u[0];  // Newton: d(lag)/dtau ~ 1, so tau moves by -lag
      if (it > 0 && lag != lag_prev) {
        const double secant = t - lag * (t - t_prev) / (lag - lag_prev);
        if (std::isfinite(secant)) next = secant;
      }
      t_prev = t;
      lag_prev = lag;
      t = next;
      sphere.centre(t, C, u);
      g = MetricAt<S>(st, C);
      lag = g(X - C, u);
      tolerance = tolerance_at(C);
    }
    if (settled) *settled = std::abs(lag) < tolerance;
    if (std::abs(lag) < tolerance || attempt == 1 || t_start == X[0]) return t;
    // Not settled: a warm start far from this point's root can leave six
    // steps short.  Where it matters, within 2 R, search again from X's own
    // time.
    double dx2 = 0.0;
    for (int k = 1; k < 4; ++k) dx2 += (X[k] - C[k]) * (X[k] - C[k]);
    if (dx2 >= 4.0 * R * R) return t;
    t = X[0];
  }
}

// |xi|^2 of sphere_local without the frame's spatial legs: the squared
// length of X - C projected orthogonally to u, g(d, d) + g(d, u)^2 / -g(u, u).
// What the intersection test needs at every sample; the legs (interpolation,
// metric and Gram–Schmidt) only colour a hit.
// t_near: where the search starts (NaN: at X's own time); set to the
// simultaneous time found, so the next point along the ray starts near it.
// Where the search does not settle, X lies on the rest slice of no centre
// event near it (the model's sphere has no point there), and an unsettled
// answer's centre may be anywhere on the worldline (a swinging centre
// passes near X again later): X is then judged from where the centre is at
// its own time, and the next search starts afresh.  Taking the unsettled
// centre made false hits: slivers of the dihole's sphere in empty sky,
// which a frame reusing the sky there did not show.
template <class S>
double sphere_distance2(const S& st, const SphereBody& sphere, const Vec4& X, double& t_near) {
  Vec4 C, u;
  MetricAt<S> g;
  bool settled = true;
  t_near = sphere_simultaneous_time(st, sphere, X, std::isnan(t_near) ? X[0] : t_near, C, u, g, &settled);
  if (!settled) {
    sphere.centre(X[0], C, u);
    g = MetricAt<S>(st, C);
    t_near = std::numeric_limits<double>::quiet_NaN();
  }
  const Vec4 d = X - C;
  const double du = g(d, u);
  return g(d, d) + du * du / -g(u, u);
}

template <class S>
Vec3 sphere_local(const S& st, const SphereBody& sphere, const Vec4& X) {
  // The simultaneous event first; the frame, with its metric and
  // Gram–Schmidt, once there.
  Vec4 C, u;
  MetricAt<S> g_centre;
  const double t = sphere_simultaneous_time(st, sphere, X, X[0], C, u, g_centre);
  const SphereFrame f = sphere.at(t);
  const Mat4 g = st.metric(f.centre);
  const Vec4 d = X - f.centre;
  return {contract(g, d, f.frame.e[1]), contract(g, d, f.frame.e[2]), contract(g, d, f.frame.e[3])};
}

// First entry of the ray into the sphere within a step that body_near_step
// (objects/bounded_body.hpp) let through, if any: the affine parameter of the crossing.  The spacetime
// tube (the centre's box [clo, chi] over the step's time range,
// grown by the tube's radius and the step's bulge) rejects most such steps before any
// sampling.
// t_near carries the last simultaneity answer along the ray (NaN: none yet),
// so the searches of consecutive steps start close to theirs.
template <class S>
[[gnu::noinline]] std::optional<double> sphere_entry(const S& st, const SphereBody& sphere, const RayStep& step,
                                                     const StepHull& hull, Vec3 clo, Vec3 chi, double& t_near) {
  const double l0 = step.t0, l1 = step.t0 + step.h;
  const RayState& a = step.start();
  const RayState& b = hull.end;
  const double chord2 = hull.chord2, quarter = hull.quarter, margin = hull.margin;
  grow_by_reach(hull, sphere, clo, chi);
  if (!boxes_overlap(hull.lo, hull.hi, clo, chi)) return std::nullopt;

  // Clip the step to the tube with the straight chord (widened each side by
  // the margin, for the bulge), then sample F = |xi|^2 - R^2 at spacing R/4
  // along what is left, so no sphere slips between samples however long
  // the step.
  const double R = sphere.radius, R2 = R * R;
  double s0 = 0.0, s1 = 1.0;
  for (int k = 0; k < 3; ++k) {
    const double d = b[k + 1] - a[k + 1];
    if (std::abs(d) < 1e-300) continue;
    double e0 = (clo[k] - a[k + 1]) / d, e1 = (chi[k] - a[k + 1]) / d;
    if (e0 > e1) std::swap(e0, e1);
    s0 = std::max(s0, e0);
    s1 = std::min(s1, e1);
  }
  const double widen = chord2 > 0.0 ? margin / std::sqrt(chord2) : 1.0;
  s0 = std::max(0.0, s0 - widen);
  s1 = std::min(1.0, s1 + widen);
  if (s0 >= s1) return std::nullopt;
  // Sample F = |xi|^2 - R^2 along what is left, sphere-tracing style (Hart
  // 1996): xi is linear in the ray point (with the metric at the sphere's
  // centre), so from a sample at distance |xi| the ray cannot reach the
  // sphere within (|xi| - R) / lip of coordinate length, lip bounding how
  // fast |xi| can change: Gershgorin on the metric, times (1 + dt/dx along
  // the step) for the sphere's motion at up to the speed of light, doubled
  // for the metric's variation.  Far samples skip ahead; near the
  // sphere the spacing is R/4, so no sphere slips between samples however
  // long the step.
  const double chord = std::sqrt(chord2);
  // Coordinate length per unit of s (the step's parameter fraction), at
  // most: the ray's coordinate speed varies along a step (it slows deep in
  // a potential well), so twice the fastest quarter's, not the chord.
  const double len = 8.0 * quarter + 2.0 * margin;
  const double spacing = 0.25 * R;
  Vec4 centre, u_centre;  // the centre alone: the frame's Gram–Schmidt is not needed here
  sphere.centre(0.5 * (a[0] + b[0]), centre, u_centre);
  const Mat4 gc = st.metric(centre);
  double row = 0.0;
  for (int i = 1; i < 4; ++i) row = std::max(row, std::abs(gc[i][0]) + std::abs(gc[i][1]) + std::abs(gc[i][2]) + std::abs(gc[i][3]));
  // The sphere moves (slower than light) while the ray's coordinate time
  // runs on by |dt| per |dx| — deep in a potential well far more than 1.
  const double time_rate = std::abs(b[0] - a[0]) / std::max(chord, 1e-300);
  const double lip = 2.0 * std::sqrt(row) * (1.0 + time_rate);
  // Samples along one step are close together: each simultaneity search
  // starts from the last one's answer.
  auto F = [&](const RayState& y) { return sphere_distance2(st, sphere, {y[0], y[1], y[2], y[3]}, t_near) - R2; };
  auto lambda_at = [&](double q) { return l0 + q * (l1 - l0); };
  double prev_s = s0, prev_l = lambda_at(s0);
  double prev_f = F(step.at(prev_l));
  double min_f = prev_f, min_l = prev_l, min_lo = prev_l, min_hi = prev_l;
  while (prev_s < s1) {
    const double dist = std::sqrt(std::max(prev_f + R2, 0.0));
    const double skip = std::max(spacing, (dist - R) / lip);
    const double q = std::min(s1, prev_s + skip / len);
    const double l = lambda_at(q);
    const double f = F(step.at(l));
    if (prev_f > 0.0 && f <= 0.0)
      return locate_crossing(step, F, prev_l, l, prev_f, f, 1e-12 * std::max(1.0, R2));
    if (f < min_f) {
      min_f = f;
      min_l = l;
      min_lo = prev_l;
      min_hi = l;  // widened below once the next sample is known
    } else if (min_hi == min_l) {
      min_hi = l;
    }
    prev_s = q;
    prev_l = l;
    prev_f = f;
  }
  // A grazing ray can dip into the sphere between two samples.  Along a
  // nearly straight segment F is nearly a parabola, so the sample nearest
  // the closest approach has F < spacing^2 / 4 when the ray enters; refine
  // the minimum there by golden-section search and take the entry before it.
  if (min_f < 0.5 * spacing * spacing && min_f > 0.0) {
    double a = min_lo, b = min_hi;
    constexpr double g = 0.6180339887498949;
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = F(step.at(c)), fd = F(step.at(d));
    // To 1e-6 R of coordinate length along the ray: where the closest
    // approach lies matters only as far as whether F dips below 0 there.
    const double tol = 1e-6 * R * (l1 - l0) / len;
    for (int it = 0; it < 60 && std::abs(b - a) > tol; ++it) {
      if (fc <= 0.0 || fd <= 0.0) break;
      if (fc < fd) {
        b = d;
        d = c;
        fd = fc;
        c = b - g * (b - a);
        fc = F(step.at(c));
      } else {
        a = c;
        c = d;
        fc = fd;
        d = a + g * (b - a);
        fd = F(step.at(d));
      }
    }
    const double inside = fc <= 0.0 ? c : (fd <= 0.0 ? d : 0.0);
    if (fc <= 0.0 || fd <= 0.0) {
      const double fa = F(step.at(min_lo));
      return locate_crossing(step, F, min_lo, inside, fa, F(step.at(inside)), 1e-12 * std::max(1.0, R2));
    }
  }
  return std::nullopt;
}

}  // namespace lc::detail
