#pragma once
// A frame ready to render: the spacetime in the chart rays are traced in, the
// observer's event and tetrad, the camera and the objects.  trace_sample()
// follows one camera ray through it; everything here is templated on the
// concrete spacetime so the metric inlines into the integrator.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "geodesic/crossing.hpp"
#include "geodesic/kerr_mino.hpp"
#include "geodesic/null_ray.hpp"
#include "geodesic/weak_field_tail.hpp"
#include "observer/ray_direction.hpp"
#include "render/camera.hpp"
#include "render/hit.hpp"
#include "render/objects.hpp"
#include "spacetime/scene_polar.hpp"

namespace lc {

template <class S>
struct SceneOf {
  S spacetime;
  Vec4 observer{};       // trace coordinates
  double observer_time;  // scene time of the observer (BL t for Kerr)
  Mat4 metric{};         // at the observer
  Tetrad frame{};
  PinholeCamera camera;
  std::optional<Disk> disk;
  Sky sky;
  std::vector<Sphere> spheres;
  RayOptions rays;
  Vec4 observer_scene{};  // the observer's event in scene coordinates, exact where the shot gave it (on the axis)
  Mat4 observer_jacobian{};  // Kerr: trace_jacobian(observer_scene), once per frame for the BL–Mino path
  // still_key() of the frame's scene where the spacetime is stationary, else
  // empty: frames with equal non-empty keys may share the samples of rays
  // that stay clear of moving objects (render/sample_memo.hpp).
  std::string still_key{};
};

// For trace_sample: a path recorder that records nothing (rendering).
struct NoPath {
  void operator()(const RayState&, double) const {}
};

using Scene = std::variant<SceneOf<Minkowski>, SceneOf<Kerr>, SceneOf<Dihole>>;

namespace detail {

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
// of DESIGN.md (X on the rest frame's slice through C).  Starts from t_start
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
// du/dt, converged in fewer steps but cost 8% more per frame.)
template <class S>
double sphere_simultaneous_time(const S& st, const Sphere& sphere, const Vec4& X, double t_start, Vec4& C, Vec4& u,
                                MetricAt<S>& g) {
  const double R = sphere.spec.radius;
  // To 1e-8 in proper time (the centre moves by less than that) near the
  // sphere; farther out sphere tracing only needs |xi| to a fraction of the
  // distance to spare: 10% of the coordinate distance beyond 1.5 R, judged
  // from the latest centre (a search that starts far from its root may end
  // near the sphere).  |xi|, the part of X - C orthogonal to u, does not
  // change to first order as C slides along u, so an unfinished lag moves it
  // far less than |lag|.  (1% cost a quarter more centre lookups for the
  // same frames.)
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
template <class S>
double sphere_distance2(const S& st, const Sphere& sphere, const Vec4& X, double& t_near) {
  Vec4 C, u;
  MetricAt<S> g;
  t_near = sphere_simultaneous_time(st, sphere, X, std::isnan(t_near) ? X[0] : t_near, C, u, g);
  const Vec4 d = X - C;
  const double du = g(d, u);
  return g(d, d) + du * du / -g(u, u);
}

template <class S>
Vec3 sphere_local(const S& st, const Sphere& sphere, const Vec4& X) {
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

inline bool boxes_overlap(const Vec3& alo, const Vec3& ahi, const Vec3& blo, const Vec3& bhi) {
  for (int k = 0; k < 3; ++k)
    if (ahi[k] < blo[k] || bhi[k] < alo[k]) return false;
  return true;
}

// How near a step may come to a sphere, by sphere_near_step's boxes.
enum class SphereReach {
  never,    // clear of everywhere the centre ever is: the sphere's motion cannot matter
  not_now,  // clear of where the centre is over the step's time range
  maybe,    // sphere_entry must look
};

// The cheap first half of sphere_entry, for every step of every ray.  First
// against the box the centre never leaves, grown by 2R and half the chord
// (a step strays from its chord by less than that), then against the
// centre's box over the step's time range (a table lookup); neither
// evaluates the step's dense output inside.
[[gnu::always_inline]] inline SphereReach sphere_near_step(const Sphere& sphere, const RayStep& step) {
  const RayState& a = step.start();
  const double l1 = step.t0 + step.h;
  Vec3 rlo, rhi, clo, chi;
  double chord1 = 0.0, b[4];  // the chord's L1 length: no square root, and >= its length
  for (int k = 0; k < 4; ++k) b[k] = step.component(k, l1);
  for (int k = 0; k < 3; ++k) chord1 += std::abs(b[k + 1] - a[k + 1]);
  const double far = 2.0 * sphere.spec.radius + 0.5 * chord1;
  for (int k = 0; k < 3; ++k) {
    rlo[k] = std::min(a[k + 1], b[k + 1]);
    rhi[k] = std::max(a[k + 1], b[k + 1]);
    clo[k] = sphere.life_lo[k] - far;
    chi[k] = sphere.life_hi[k] + far;
  }
  if (!boxes_overlap(rlo, rhi, clo, chi)) return SphereReach::never;
  sphere.bounds(a[0], b[0], clo, chi);
  for (int k = 0; k < 3; ++k) {
    clo[k] -= far;
    chi[k] += far;
  }
  return boxes_overlap(rlo, rhi, clo, chi) ? SphereReach::maybe : SphereReach::not_now;
}

// Where a step goes, for the sphere tests that sphere_near_step's coarse
// boxes let through: the box of its ends and of its points at 1/4, 1/2 and
// 3/4, and how far it may stray beyond: twice the largest distance of those
// points from the chord (a step is a smooth, nearly polynomial arc).  Long
// straight steps (far from the holes) then keep a tight box instead of one
// grown by a fraction of their length.
struct StepHull {
  RayState end{};
  Vec3 lo{}, hi{};
  double chord2 = 0.0;   // squared chord
  double quarter = 0.0;  // the longest chord of a quarter of the step
  double margin = 0.0;   // how far beyond the box the step may stray
};

inline StepHull step_hull(const RayStep& step) {
  StepHull h;
  const double l0 = step.t0, l1 = step.t0 + step.h;
  const RayState& a = step.start();
  const RayState& b = h.end = step.at(l1);
  for (int k = 0; k < 3; ++k) {
    h.chord2 += (b[k + 1] - a[k + 1]) * (b[k + 1] - a[k + 1]);
    h.lo[k] = std::min(a[k + 1], b[k + 1]);
    h.hi[k] = std::max(a[k + 1], b[k + 1]);
  }
  double bulge = 0.0;
  RayState prev = a;
  for (const double q : {0.25, 0.5, 0.75, 1.0}) {
    const RayState m = q == 1.0 ? b : step.at(l0 + q * (l1 - l0));
    double d2 = 0.0, seg2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      h.lo[k] = std::min(h.lo[k], m[k + 1]);
      h.hi[k] = std::max(h.hi[k], m[k + 1]);
      const double off = m[k + 1] - (a[k + 1] + q * (b[k + 1] - a[k + 1]));
      d2 += off * off;
      seg2 += (m[k + 1] - prev[k + 1]) * (m[k + 1] - prev[k + 1]);
    }
    bulge = std::max(bulge, std::sqrt(d2));
    h.quarter = std::max(h.quarter, std::sqrt(seg2));
    prev = m;
  }
  h.margin = 2.0 * bulge + 1e-9 * std::sqrt(h.chord2);
  return h;
}

// Whether the step (its hull) comes within 2R of the box [lo, hi] of
// centres: the test both for "may meet the sphere now" (the centre's box
// over the step's time range) and for "may depend on the sphere's motion"
// (the box it never leaves).
// grow_by_reach grows such a box of centres in place (the tube sphere_entry
// clips the step to).
inline void grow_by_reach(const StepHull& h, const Sphere& sphere, Vec3& lo, Vec3& hi) {
  const double grow = 2.0 * sphere.spec.radius + h.margin;
  for (int k = 0; k < 3; ++k) {
    lo[k] -= grow;
    hi[k] += grow;
  }
}

inline bool hull_near_centres(const StepHull& h, const Sphere& sphere, Vec3 lo, Vec3 hi) {
  grow_by_reach(h, sphere, lo, hi);
  return boxes_overlap(h.lo, h.hi, lo, hi);
}

// First entry of the ray into the sphere within a step that sphere_near_step
// let through, if any: the affine parameter of the crossing.  The spacetime
// tube (the centre's box over the step's time range, grown by 2R and the
// step's bulge) rejects most such steps before any sampling.
// t_near carries the last simultaneity answer along the ray (NaN: none yet),
// so the searches of consecutive steps start close to theirs.
template <class S>
[[gnu::noinline]] std::optional<double> sphere_entry(const S& st, const Sphere& sphere, const RayStep& step,
                                                     const StepHull& hull, double& t_near) {
  const double l0 = step.t0, l1 = step.t0 + step.h;
  const RayState& a = step.start();
  const RayState& b = hull.end;
  const double chord2 = hull.chord2, quarter = hull.quarter, margin = hull.margin;
  Vec3 clo, chi;
  sphere.bounds(a[0], b[0], clo, chi);
  grow_by_reach(hull, sphere, clo, chi);
  if (!boxes_overlap(hull.lo, hull.hi, clo, chi)) return std::nullopt;

  // Clip the step to the tube with the straight chord (widened each side by
  // the margin, for the bulge), then sample F = |xi|^2 - R^2 at spacing R/4
  // along what is left, so no sphere slips between samples however long
  // the step.
  const double R = sphere.spec.radius, R2 = R * R;
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

}  // namespace detail

namespace detail {

// The sky seen by a ray that escaped at the trace-coordinate event x with
// momentum p: fills out.kind and out.color.
template <class S>
void sky_sample(const SceneOf<S>& sc, const Vec4& x, const Vec4& p, RaySample& out) {
  const S& st = sc.spacetime;
  // Escape direction: the spatial tangent, bent by the deflection still to
  // come between here and infinity.  The dihole's far field is the
  // isotropic monopole of weak_field_tail.hpp, exact to O(M d^2 / r^3);
  // elsewhere (Kerr–Schild) its first order, (2M/r) tan(psi/2) towards the
  // centre (psi: angle between position and direction).  Without it the sky
  // would sit ~2M/R radians off at the escape radius R.
  Vec4 dx, dp;
  st.hamiltonian_rhs(x, p, dx, dp);
  Vec3 d = {dx[1], dx[2], dx[3]};
  const double dn = norm3(d);
  for (auto& c : d) c /= dn;
  const double M = st.asymptotic_mass();
  if constexpr (std::is_same_v<S, Dihole>) {
    d = isotropic_escape_direction({x[1], x[2], x[3]}, d, M);
  } else if (M > 0.0) {
    const double rho = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    const Vec3 rh = {x[1] / rho, x[2] / rho, x[3] / rho};
    const double c = std::clamp(rh[0] * d[0] + rh[1] * d[1] + rh[2] * d[2], -1.0, 1.0);
    const double psi = std::acos(c);
    if (psi > 1e-9) {
      const double delta = 2.0 * M / rho * std::tan(0.5 * psi);
      // Unit vector in the plane, perpendicular to d, pointing away from the centre side.
      Vec3 w = {rh[0] - c * d[0], rh[1] - c * d[1], rh[2] - c * d[2]};
      const double wn = norm3(w);
      for (auto& q : w) q /= wn;
      const double cd = std::cos(delta), sd = std::sin(delta);
      d = {cd * d[0] - sd * w[0], cd * d[1] - sd * w[1], cd * d[2] - sd * w[2]};
    }
  }
  out.kind = HitKind::sky;
  const double theta = std::acos(std::clamp(d[2], -1.0, 1.0));
  double sphi = std::atan2(d[1], d[0]);
  if (sphi < 0) sphi += two_pi;
  out.color = sc.sky.color(theta, sphi);
}


// The general path: the Hamiltonian in the trace chart (Kerr–Schild for
// Kerr).  One ray's start, its visitor (spheres, the disk, plane crossings)
// and its result, apart from the integration itself, so that rays can also
// be integrated several at once (render/trace_batch.hpp).
template <class S, class OnStep>
class HamiltonianRay {
 public:
  HamiltonianRay(const SceneOf<S>& sc, const Vec3& n, OnStep& on_step)
      : sc_(sc), on_step_(on_step), p0_(backward_ray_momentum(sc.metric, sc.frame, n)) {}

  const Vec4& momentum() const { return p0_; }

  // The visitor of trace_null_ray: true when the ray hit an object (res filled).
  bool visit(const RayStep& step, RayResult& res) {
    const S& st = sc_.spacetime;
    on_step_(step.start(), step.t0);
    const double l1 = step.t0 + step.h;
    double best = l1 + 1.0;
    int hit_sphere = -1;
    std::optional<StepHull> hull;  // for the spheres the coarse boxes let through
    for (std::size_t k = 0; k < sc_.spheres.size(); ++k) {
      const Sphere& sphere = sc_.spheres[k];
      const SphereReach reach = detail::sphere_near_step(sphere, step);
      if (reach == SphereReach::never) continue;
      const bool timeless_yet = !out_.depends_on_time;
      if (reach == SphereReach::not_now && !timeless_yet) continue;
      if (!hull) hull = step_hull(step);
      // Near a moving sphere's path what the ray sees depends on where the
      // sphere is at the frame's time: no other frame may reuse it.  Near
      // one at rest too, though only to rounding: the sphere test works in
      // absolute coordinate time, so shifted in time its samples round
      // differently, and a grazing hit could flip.
      if (timeless_yet && hull_near_centres(*hull, sphere, sphere.life_lo, sphere.life_hi)) out_.depends_on_time = true;
      if (reach == SphereReach::not_now) continue;
      double none = std::numeric_limits<double>::quiet_NaN();
      double& t_near = k < sphere_times_.size() ? sphere_times_[k] : none;
      if (auto l = detail::sphere_entry(st, sphere, step, *hull, t_near); l && *l < best) {
        best = *l;
        hit_sphere = static_cast<int>(k);
      }
    }
    const double z0 = step.start()[3], z1 = step.component(3, l1);
    if ((z0 > 0.0) != (z1 > 0.0) && z0 != 0.0) {
      // Without a disk a crossing only counts (hit.order); it is located only
      // when a sphere hit in the same step makes its order matter.
      const double lz = sc_.disk || hit_sphere >= 0
                            ? locate_crossing(step, [](const RayState& y) { return y[3]; }, z0, z1)
                            : step.t0;
      if (!sc_.disk) {
        if (lz < best) ++crossings_;
      } else if (lz < best) {
        const RayState y = step.at(lz);
        double t, r, phi;
        scene_polar(st, {y[0], y[1], y[2], y[3]}, t, r, phi);
        if (r >= sc_.disk->spec.inner && r <= sc_.disk->spec.outer)
          return hit(HitKind::disk, sc_.disk->color(r, phi), y, lz, res);
        ++crossings_;
      }
    }
    if (hit_sphere >= 0) {
      const RayState y = step.at(best);
      const Sphere& sp = sc_.spheres[hit_sphere];
      return hit(HitKind::object, sp.color(detail::sphere_local(st, sp, {y[0], y[1], y[2], y[3]})), y, best, res);
    }
    return false;
  }

  // The sample, once the integration has ended with `res`.
  RaySample finish(const RayResult& res) {
    out_.steps = res.steps;
    out_.reason = res.reason;
    out_.end = res.y;
    out_.lambda_end = res.lambda;
    if (res.reason == StopReason::hit) return out_;
    const Vec4 x = {res.y[0], res.y[1], res.y[2], res.y[3]};
    double t, r, phi;
    scene_polar(sc_.spacetime, x, t, r, phi);
    out_.r = r;
    out_.phi = phi;
    out_.t = t - sc_.observer_time;
    out_.order = crossings_;
    if (res.reason == StopReason::horizon) {
      out_.kind = HitKind::horizon;
      return out_;
    }
    if (res.reason != StopReason::escaped) return out_;  // gave up: black, kind 4
    sky_sample(sc_, x, {res.y[4], res.y[5], res.y[6], res.y[7]}, out_);
    return out_;
  }

 private:
  // Ends the ray at the event y (affine parameter lambda) on an object.
  bool hit(HitKind kind, const Color& color, const RayState& y, double lambda, RayResult& res) {
    double t, r, phi;
    scene_polar(sc_.spacetime, {y[0], y[1], y[2], y[3]}, t, r, phi);
    out_.kind = kind;
    out_.color = color;
    out_.r = r;
    out_.phi = phi;
    out_.t = t - sc_.observer_time;
    out_.order = crossings_;
    res.reason = StopReason::hit;
    res.y = y;
    res.lambda = lambda;
    return true;
  }

  const SceneOf<S>& sc_;
  OnStep& on_step_;
  Vec4 p0_;
  RaySample out_;
  int crossings_ = 0;
  // Per sphere (the first few), the last simultaneity answer along this ray.
  std::array<double, 4> sphere_times_ = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN(),
                                         std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
};

template <class S, class OnStep>
RaySample trace_sample_hamiltonian(const SceneOf<S>& sc, const Vec3& n, OnStep& on_step) {
  HamiltonianRay<S, OnStep> ray(sc, n, on_step);
  const RayResult res = trace_null_ray(sc.spacetime, sc.observer, ray.momentum(), sc.rays,
                                       [&](const RayStep& step, RayResult& r) { return ray.visit(step, r); });
  return ray.finish(res);
}

// The Kerr fast path (geodesic/kerr_mino.hpp): Boyer–Lindquist and Mino
// time, for Kerr scenes without spheres.  The same results as the general
// path to the integration tolerance; the start, the end and what `lightcone
// trace` records are converted to Kerr–Schild.  One ray's start, its
// visitor (disk, escape, the layers' events) and its result, apart from
// the integration itself, so that rays can also be integrated several at
// once (render/trace_batch.hpp).
template <class OnStep>
class MinoRay {
 public:
  MinoRay(const SceneOf<Kerr>& sc, const Vec3& n, OnStep& on_step)
      : sc_(sc), on_step_(on_step), start_(make_start(sc, n)), clock_(start_.rhs, start_.y0[1]),
        u_escape_(1.0 / sc.rays.escape_radius), u_capture_(capture_radius() > 0.0 ? 1.0 / capture_radius() : 1e300),
        at_escape_{start_.y0, start_.y0[0]} {}

  const KerrMinoStart& start() const { return start_; }
  double capture_radius() const { return sc_.spacetime.mass() > 0.0 ? sc_.spacetime.capture_radius() : 0.0; }

  // The visitor of trace_kerr_mino: sees each accepted step; true when the
  // ray hit the disk (res filled).
  bool visit(const MinoStep& step, MinoResult& res) {
    const double u0 = step.start()[1];
    // The step ends at infinity if u reaches 0 in it; nothing beyond counts.
    double l1 = step.t0 + step.h, u1 = step.component(1, l1);
    if (u1 <= 0.0) {
      l1 = locate_crossing(step, [](const MinoState& y) { return y[1]; }, u0, u1);
      u1 = 0.0;
    }
    clock_.see(step, l1);
    if constexpr (!std::is_same_v<std::decay_t<OnStep>, NoPath>)
      on_step_(trace_state(event_at(step, step.t0)), step.start()[7]);
    const double c0 = step.start()[2], c1 = step.component(2, l1);
    if ((c0 > 0.0) != (c1 > 0.0) && c0 != 0.0) {
      const double lz = locate_crossing(step, [](const MinoState& y) { return y[2]; }, step.t0, l1, c0, c1);
      const Event e = event_at(step, lz);
      fill_event(e);
      if (sc_.disk && out_.r >= sc_.disk->spec.inner && out_.r <= sc_.disk->spec.outer) {
        out_.kind = HitKind::disk;
        out_.color = sc_.disk->color(out_.r, out_.phi);
        res.reason = StopReason::hit;
        res.y = e.y;
        res.lambda = lz;
        at_hit_ = e;
        return true;
      }
      if (e.y[1] > u_escape_) ++crossings_;  // as the Kerr–Schild path counts: up to the escape radius
    }
    if (u0 > u_escape_ && u1 <= u_escape_) {
      const double le = locate_crossing(
          step, [u = u_escape_](const MinoState& y) { return y[1] - u; }, step.t0, l1, u0 - u_escape_, u1 - u_escape_);
      at_escape_ = event_at(step, le);
    }
    if (u1 > u_capture_) {
      // The layers' event of a horizon pixel is on the capture surface, not
      // wherever the step ended (for Schwarzschild, inside the horizon).
      const double lc = locate_crossing(
          step, [u = u_capture_](const MinoState& y) { return y[1] - u; }, u0 - u_capture_, u1 - u_capture_, 1e-12);
      at_capture_ = event_at(step, lc);
    }
    if (res.reason == StopReason::escaped) {
      // At infinity phi_shift vanishes: the Kerr–Schild direction is the BL
      // angular position (sin th < 0 included: the same point).
      const MinoState y = step.at(l1);
      direction_ = {y[3] * std::cos(y[4]), y[3] * std::sin(y[4]), y[2]};
    }
    return false;
  }

  // The sample, once the integration has ended with `res`.
  RaySample finish(const MinoResult& res) {
    out_.steps = res.steps;
    out_.reason = res.reason;
    const Event last = res.reason == StopReason::escaped   ? at_escape_
                       : res.reason == StopReason::horizon ? at_capture_
                       : res.reason == StopReason::hit     ? at_hit_
                                                           : Event{res.y, clock_.time(res.y, res.lambda)};
    // The end in trace coordinates costs a Jacobian, its inverse and two
    // logarithms: only `lightcone trace` (a path recorder) reads it.
    if constexpr (!std::is_same_v<std::decay_t<OnStep>, NoPath>) {
      out_.end = trace_state(last);
      out_.lambda_end = last.y[7];
    }
    if (res.reason == StopReason::hit) return out_;
    fill_event(last);
    if (res.reason == StopReason::horizon) {
      out_.kind = HitKind::horizon;
      return out_;
    }
    if (res.reason != StopReason::escaped) return out_;  // gave up: black, kind 4
    out_.kind = HitKind::sky;
    const double n2 = norm3(direction_);
    const double theta = std::acos(std::clamp(direction_[2] / n2, -1.0, 1.0));
    double sphi = std::atan2(direction_[1], direction_[0]);
    if (sphi < 0) sphi += two_pi;
    out_.color = sc_.sky.color(theta, sphi);
    return out_;
  }

 private:
  // A point of the ray and its Boyer–Lindquist coordinate time (the state
  // holds tau, see kerr_mino.hpp).
  struct Event {
    MinoState y;
    double t;
  };
  // The event at Mino time lambda of the step the clock saw last.
  Event event_at(const MinoStep& step, double lambda) const {
    const MinoState y = step.at(lambda);
    return {y, clock_.time(y, lambda)};
  }

  static KerrMinoStart make_start(const SceneOf<Kerr>& sc, const Vec3& n) {
    const Kerr& st = sc.spacetime;
    const Vec4 p_ks = backward_ray_momentum(sc.metric, sc.frame, n);
    auto bl_momentum = [&](const Vec4& s) {
      const Mat4 J = st.trace_jacobian(s);
      Vec4 p{};
      for (int nu = 0; nu < 4; ++nu)
        for (int mu = 0; mu < 4; ++mu) p[nu] += p_ks[mu] * J[mu][nu];
      return p;
    };
    Vec4 s0 = sc.observer_scene;
    Vec4 p_bl{};
    for (int nu = 0; nu < 4; ++nu)
      for (int mu = 0; mu < 4; ++mu) p_bl[nu] += p_ks[mu] * sc.observer_jacobian[mu][nu];
    if (std::abs(std::sin(s0[2])) < spin_axis_sine) {
      // On the axis every phi names the observer's point, and the ray leaves it
      // along one meridian: p_theta at phi is A cos(phi) + B sin(phi) from the
      // meridians phi = 0 and pi/2, largest (the ray's own) at atan2(B, A).
      // (At theta = pi that sends theta beyond pi: sin theta < 0 stands for
      // the same point, see kerr_mino.hpp.)
      const Vec4 pa = bl_momentum({s0[0], s0[1], s0[2], 0.0});
      const Vec4 pb = bl_momentum({s0[0], s0[1], s0[2], 0.5 * pi});
      s0[3] = std::atan2(pb[2], pa[2]);
      p_bl[2] = std::hypot(pa[2], pb[2]);
      p_bl[3] = 0.0;
    }
    return kerr_mino_start(st.mass(), st.spin(), s0, p_bl, sc.rays.escape_radius);
  }
  // An event as a trace-coordinate state (x^mu, p_mu), for the path
  // recorder and the layers' end event.
  RayState trace_state(const Event& e) const {
    const Kerr& st = sc_.spacetime;
    Vec4 s, p;
    kerr_mino_event(start_.rhs, e.y, s, p);
    s[0] = e.t;
    // On the spin axis the Boyer–Lindquist chart is singular (its Jacobian
    // has no inverse); a point 1e-12 rad off it is the same to rounding.
    if (std::abs(std::sin(s[2])) < 1e-12) s[2] = s[2] < 0.5 * pi ? 1e-12 : pi - 1e-12;
    const Mat4 Ji = inverse(st.trace_jacobian(s));
    const Vec4 x = st.trace_from_scene(s);
    Vec4 pk{};
    for (int mu = 0; mu < 4; ++mu)
      for (int nu = 0; nu < 4; ++nu) pk[mu] += p[nu] * Ji[nu][mu];
    return RayState{x[0], x[1], x[2], x[3], pk[0], pk[1], pk[2], pk[3]};
  }
  void fill_event(const Event& e) {
    Vec4 s, p;
    kerr_mino_event(start_.rhs, e.y, s, p);
    out_.r = s[1];
    out_.phi = s[3];
    out_.t = e.t - sc_.observer_time;
    out_.order = crossings_;
  }

  const SceneOf<Kerr>& sc_;
  OnStep& on_step_;
  KerrMinoStart start_;
  MinoClock clock_;
  double u_escape_;
  double u_capture_;  // 1 / capture radius (1e300: nothing is captured)
  Event at_escape_;   // where r passed the escape radius (the layers' end event)
  Event at_capture_{};  // where r passed the capture radius (the same for the horizon)
  Event at_hit_{};      // where the ray met the disk
  Vec3 direction_{};  // at infinity, in the Kerr–Schild Cartesian frame
  RaySample out_;
  int crossings_ = 0;
};

template <class OnStep>
RaySample trace_sample_mino(const SceneOf<Kerr>& sc, const Vec3& n, OnStep& on_step) {
  MinoRay<OnStep> ray(sc, n, on_step);
  const MinoResult res = trace_kerr_mino(ray.start(), ray.capture_radius(), sc.rays,
                                         [&](const MinoStep& step, MinoResult& r) { return ray.visit(step, r); });
  return ray.finish(res);
}

}  // namespace detail

// Traces the camera ray along local direction n (on the observer's legs).
// OnStep(const RayState& y, double sigma) sees the start of every accepted
// step in trace coordinates with its affine parameter (for `lightcone
// trace`; NoPath when rendering).  Kerr scenes without spheres take the
// Boyer–Lindquist–Mino path unless sc.rays.kerr_chart says otherwise.
template <class S, class OnStep>
RaySample trace_sample(const SceneOf<S>& sc, const Vec3& n, OnStep&& on_step) {
  if constexpr (std::is_same_v<S, Kerr>)
    if (sc.spheres.empty() && sc.rays.kerr_chart == KerrChart::boyer_lindquist_mino)
      return detail::trace_sample_mino(sc, n, on_step);
  return detail::trace_sample_hamiltonian(sc, n, on_step);
}

}  // namespace lc
