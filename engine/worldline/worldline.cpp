#include "worldline/worldline.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "geodesic/christoffel.hpp"
#include "geodesic/geodesic_solver.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace {

// Cubic Hermite basis on [0,1].
inline void hermite(double s, double& h00, double& h10, double& h01, double& h11) {
  const double s2 = s * s, s3 = s2 * s;
  h00 = 2 * s3 - 3 * s2 + 1;
  h10 = s3 - 2 * s2 + s;
  h01 = -2 * s3 + 3 * s2;
  h11 = s3 - s2;
}

}  // namespace

std::string WorldlineSpec::key() const {
  std::string k = describe(spacetime, true);
  for (double v : start) k += fmt::format(":{:a}", v);
  for (double v : velocity) k += fmt::format(":{:a}", v);
  return k + fmt::format(":{:a}", duration);
}

Worldline Worldline::integrate(const WorldlineSpec& spec) {
  if (!(spec.duration > 0.0))
    throw std::invalid_argument(fmt::format("{}: worldline duration must be > 0", spec.where));
  Worldline w;
  w.spacetime_ = trace_chart(spec.spacetime);
  GeodesicProblem pb;
  pb.spacetime = w.spacetime_;
  pb.kind = CurveKind::timelike;
  pb.stop_parameter = StopParameter::proper_time;
  pb.stop_value = spec.duration;
  // Dense enough that Hermite interpolation is far below pixel accuracy:
  // error ~ (dtau)^4 |x''''|, at most 0.05 M of proper time per step.
  pb.samples = static_cast<int>(std::clamp(std::ceil(spec.duration / 0.05), 200.0, 2.0e6)) + 1;
  std::visit(
      [&](const auto& st) {
        const Vec4 x0 = st.trace_from_scene(spec.start);
        if (const std::string_view why = st.why_no_observer(x0); !why.empty())
          throw std::invalid_argument(fmt::format("{}: the worldline starts {}", spec.where, why));
        Tetrad frame;
        try {
          frame = boost(velocity_reference_frame(st, spec.start), spec.velocity);
        } catch (const ObserverError& e) {
          throw std::invalid_argument(fmt::format("{}: worldline: {}", spec.where, e.what()));
        }
        pb.x0 = x0;
        pb.u0 = frame.e[0];
        pb.tetrad = frame;
      },
      w.spacetime_.kinds());
  const GeodesicPath path = solve_geodesic(pb);
  if (path.reason != StopReason::reached)
    throw std::invalid_argument(fmt::format(
        "{}: the worldline stopped early ({}) at proper time {:.6g} of {:.6g}; shorten its duration",
        spec.where, to_string(path.reason), path.samples.back().lambda, spec.duration));
  w.duration_ = spec.duration;
  w.dtau_ = spec.duration / (pb.samples - 1);
  w.samples_.reserve(path.samples.size());
  for (const auto& s : path.samples) w.samples_.push_back({s.x, s.u, Tetrad{s.e}});
  // The coordinate-time table: twice as many steps as in proper time
  // (coordinate time runs up to a few times faster than proper time deep in
  // a potential well).  Each sample comes from the proper-time samples by
  // Hermite interpolation in tau of the position (derivative u) and of the
  // 4-velocity (derivative du/dtau = -Gamma(u, u), from the metric), with
  // tau(t) inverted by proper_time_at; then dx/dt = u / u^0 and
  // du/dt = (du/dtau) / u^0.
  std::vector<Vec4> dudtau(w.samples_.size());
  const std::size_t n_t = 2 * (w.samples_.size() - 1) + 1;
  w.dt_ = (w.end_time() - w.start_time()) / static_cast<double>(n_t - 1);
  w.by_time_.resize(n_t);
  w.spans_.reserve(n_t);
  std::visit(
      [&](const auto& st) {
        auto acceleration = [&](const Vec4& x, const Vec4& u) { return transport_rate(christoffel(st, x), u, u); };
        for (std::size_t i = 0; i < w.samples_.size(); ++i)
          dudtau[i] = acceleration(w.samples_[i].x, w.samples_[i].u);
        for (std::size_t k = 0; k < n_t; ++k) {
          TimeSample& ts = w.by_time_[k];
          const double t = k + 1 == n_t ? w.end_time() : w.start_time() + static_cast<double>(k) * w.dt_;
          const double f = w.proper_time_at(t) / w.dtau_;
          const std::size_t i = std::min(static_cast<std::size_t>(f), w.samples_.size() - 2);
          const double q = f - static_cast<double>(i);
          const Sample& sa = w.samples_[i];
          const Sample& sb = w.samples_[i + 1];
          double h00, h10, h01, h11;
          hermite(q, h00, h10, h01, h11);
          for (int m = 0; m < 4; ++m) {
            ts.x[m] = h00 * sa.x[m] + h10 * w.dtau_ * sa.u[m] + h01 * sb.x[m] + h11 * w.dtau_ * sb.u[m];
            ts.u[m] = h00 * sa.u[m] + h10 * w.dtau_ * dudtau[i][m] + h01 * sb.u[m] + h11 * w.dtau_ * dudtau[i + 1][m];
          }
          const Vec4 acc = acceleration(ts.x, ts.u);
          for (int m = 0; m < 4; ++m) {
            ts.dxdt[m] = ts.u[m] / ts.u[0];
            ts.dudt[m] = acc[m] / ts.u[0];
          }
          w.spans_.push_back(
              rest_space_span(orthonormalize(st.metric(ts.x), {ts.u, Vec4{0, 1, 0, 0}, Vec4{0, 0, 1, 0}, Vec4{0, 0, 0, 1}},
                                             "worldline")));
        }
      },
      w.spacetime_.kinds());
  // The top speed of the Hermite interpolant: per step and axis, dx/dt is a
  // quadratic in the step's fraction q, largest in size at an end or at its
  // vertex.
  double top2 = 0.0;
  for (std::size_t k = 0; k + 1 < n_t; ++k) {
    const TimeSample& a = w.by_time_[k];
    const TimeSample& b = w.by_time_[k + 1];
    double speed2 = 0.0;
    for (int m = 1; m < 4; ++m) {
      // dx/dt(q) = 6 (q^2 - q) (x_a - x_b) / dt + (3q^2 - 4q + 1) v_a + (3q^2 - 2q) v_b
      const double secant = (a.x[m] - b.x[m]) / w.dt_;
      const double c2 = 6.0 * secant + 3.0 * a.dxdt[m] + 3.0 * b.dxdt[m];
      const double c1 = -6.0 * secant - 4.0 * a.dxdt[m] - 2.0 * b.dxdt[m];
      const double c0 = a.dxdt[m];
      double top = std::max(std::abs(c0), std::abs(c2 + c1 + c0));
      if (c2 != 0.0) {
        const double q = -c1 / (2.0 * c2);
        if (q > 0.0 && q < 1.0) top = std::max(top, std::abs((c2 * q + c1) * q + c0));
      }
      speed2 += top * top;
    }
    top2 = std::max(top2, speed2);
  }
  w.top_speed_ = std::sqrt(top2);
  for (std::size_t c = 0; c * kChunk < n_t; ++c) {
    std::array<Vec3, 2> b = {Vec3{1e300, 1e300, 1e300}, Vec3{-1e300, -1e300, -1e300}};
    double top_acceleration = 0.0;
    for (std::size_t i = c * kChunk; i <= std::min(n_t - 1, (c + 1) * kChunk); ++i) {
      for (int k = 0; k < 3; ++k) {
        b[0][k] = std::min(b[0][k], w.by_time_[i].x[k + 1]);
        b[1][k] = std::max(b[1][k], w.by_time_[i].x[k + 1]);
      }
      if (i + 1 < n_t) top_acceleration = std::max(top_acceleration, w.step_acceleration(i));
    }
    w.chunk_bounds_.push_back(b);
    w.chunk_acceleration_.push_back(top_acceleration);
  }
  return w;
}

WorldlineEvent Worldline::interpolate(std::size_t i, double s) const {
  const Sample& a = samples_[i];
  const Sample& b = samples_[std::min(i + 1, samples_.size() - 1)];
  double h00, h10, h01, h11;
  hermite(s, h00, h10, h01, h11);
  WorldlineEvent ev;
  ev.tau = (static_cast<double>(i) + s) * dtau_;
  for (int m = 0; m < 4; ++m) ev.x[m] = h00 * a.x[m] + h10 * dtau_ * a.u[m] + h01 * b.x[m] + h11 * dtau_ * b.u[m];
  // Legs: linear blend, then re-orthonormalised in the metric at the event
  // (the blend is O(dtau^2) off; Gram–Schmidt restores orthonormality).
  std::array<Vec4, 4> blend;
  for (int l = 0; l < 4; ++l) blend[l] = (1.0 - s) * a.e.e[l] + s * b.e.e[l];
  const Mat4 g = std::visit([&](const auto& st) { return st.metric(ev.x); }, spacetime_.kinds());
  try {
    ev.frame = orthonormalize(g, blend, "worldline");
  } catch (const ObserverError&) {
    // Close to a horizon the trace chart is singular on (Kerr's outgoing
    // Kerr-Schild form, regular for rays traced back, at the future
    // horizon a fall crosses) the samples' components grow so fast that a
    // blend of two future-pointing legs, measured in the metric between
    // them, may not be timelike: carry sample a's event and frame to the
    // proper time instead, by the geodesic and transport equations.
    if (s == 0.0) throw;
    return transported(a, s * dtau_, ev.tau);
  }
  return ev;
}

WorldlineEvent Worldline::transported(const Sample& from, double dtau, double tau) const {
  GeodesicProblem pb;
  pb.spacetime = spacetime_;
  pb.kind = CurveKind::timelike;
  pb.stop_parameter = StopParameter::proper_time;
  pb.stop_value = dtau;
  pb.x0 = from.x;
  pb.u0 = from.u;
  pb.tetrad = from.e;
  const GeodesicPath path = solve_geodesic(pb);
  if (path.reason != StopReason::reached)
    throw ObserverError(fmt::format("worldline: the frame cannot be carried to proper time {:.6g} ({})", tau,
                                    to_string(path.reason)));
  const GeodesicSample& end = path.samples.back();
  WorldlineEvent ev;
  ev.tau = tau;
  ev.x = end.x;
  const Mat4 g = std::visit([&](const auto& st) { return st.metric(ev.x); }, spacetime_.kinds());
  ev.frame = orthonormalize(g, end.e, "worldline");
  return ev;
}

WorldlineEvent Worldline::at_proper_time(double tau) const {
  tau = std::clamp(tau, 0.0, duration_);
  const double f = tau / dtau_;
  const std::size_t i = std::min(static_cast<std::size_t>(f), samples_.size() - 2);
  return interpolate(i, f - static_cast<double>(i));
}

std::size_t Worldline::sample_index_at(double t) const {
  // t(tau) increases along a future-directed worldline, nearly linearly:
  // guess the step by proportion, gallop to bracket it, bisect within the
  // bracket.  (A plain bisection over ~10^4 samples, twice per ray step near
  // a moving sphere, was a tenth of a dihole frame.)  Assumes front <= t < back.
  const std::size_t n = samples_.size();
  const double t0 = samples_.front().x[0], t1 = samples_.back().x[0];
  const std::size_t g = std::min(n - 2, static_cast<std::size_t>((t - t0) / (t1 - t0) * static_cast<double>(n - 1)));
  std::size_t lo = g, hi = g + 1;  // want samples_[lo].t <= t < samples_[hi].t
  if (samples_[g].x[0] <= t) {
    std::size_t step = 1;
    while (hi < n && samples_[hi].x[0] <= t) {
      lo = hi;
      hi = std::min(n, hi + step);
      step *= 2;
    }
  } else {
    std::size_t step = 1;
    hi = g;
    lo = g >= step ? g - step : 0;
    while (lo > 0 && samples_[lo].x[0] > t) {
      hi = lo;
      step *= 2;
      lo = lo >= step ? lo - step : 0;
    }
  }
  auto it = std::upper_bound(samples_.begin() + static_cast<std::ptrdiff_t>(lo),
                             samples_.begin() + static_cast<std::ptrdiff_t>(hi), t,
                             [](double v, const Sample& s) { return v < s.x[0]; });
  return std::min(n - 2, static_cast<std::size_t>(it - samples_.begin()) - 1);
}

double Worldline::proper_time_at(double t) const {
  if (t <= samples_.front().x[0]) return 0.0;
  if (t >= samples_.back().x[0]) return duration_;
  // The step holding t, then the Hermite cubic of t(tau) inverted by Newton
  // from the linear guess (quadratic convergence: stop once it settles).
  const std::size_t i = sample_index_at(t);
  const Sample& a = samples_[i];
  const Sample& b = samples_[i + 1];
  double s = (t - a.x[0]) / (b.x[0] - a.x[0]);
  for (int it2 = 0; it2 < 4; ++it2) {
    double h00, h10, h01, h11;
    hermite(s, h00, h10, h01, h11);
    const double ts = h00 * a.x[0] + h10 * dtau_ * a.u[0] + h01 * b.x[0] + h11 * dtau_ * b.u[0];
    const double dts = (6 * s * s - 6 * s) * a.x[0] + (3 * s * s - 4 * s + 1) * dtau_ * a.u[0] +
                       (-6 * s * s + 6 * s) * b.x[0] + (3 * s * s - 2 * s) * dtau_ * b.u[0];
    const double next = std::clamp(s - (ts - t) / dts, 0.0, 1.0);
    const bool settled = std::abs(next - s) < 1e-14;
    s = next;
    if (settled) break;
  }
  return (static_cast<double>(i) + s) * dtau_;
}

double Worldline::step_acceleration(std::size_t k) const {
  // d2x/dt2 of a cubic Hermite step is linear in its fraction q, so its size
  // is largest at an end: dt^2 x'' = (12q - 6)(x_a - x_b) + dt ((6q - 4) v_a + (6q - 2) v_b).
  const TimeSample& a = by_time_[k];
  const TimeSample& b = by_time_[k + 1];
  double at0 = 0.0, at1 = 0.0;
  for (int m = 1; m < 4; ++m) {
    const double jump = (a.x[m] - b.x[m]) / (dt_ * dt_);
    const double q0 = -6.0 * jump + (-4.0 * a.dxdt[m] - 2.0 * b.dxdt[m]) / dt_;
    const double q1 = 6.0 * jump + (2.0 * a.dxdt[m] + 4.0 * b.dxdt[m]) / dt_;
    at0 += q0 * q0;
    at1 += q1 * q1;
  }
  return std::sqrt(std::max(at0, at1));
}

double Worldline::coordinate_extent(double radius) const {
  double release2 = 0.0;
  for (int m = 1; m < 4; ++m) release2 += by_time_.front().dxdt[m] * by_time_.front().dxdt[m];
  double top = 0.0;
  for (std::size_t k = 0; k < by_time_.size(); ++k) {
    const double t = by_time_[k].x[0], lag = spans_[k].tilt * radius;
    double acceleration = 0.0;
    for (std::size_t c = time_index(t - lag) / kChunk; c <= time_index(t + lag) / kChunk; ++c)
      acceleration = std::max(acceleration, chunk_acceleration_[c]);
    double off = spans_[k].stretch * radius + 0.5 * acceleration * lag * lag;
    if (t - lag < start_time()) off += std::sqrt(release2) * lag;
    top = std::max(top, off);
  }
  return 1.05 * top;
}

std::size_t Worldline::time_index(double t) const {
  const double f = (t - start_time()) / dt_;
  if (!(f > 0.0)) return 0;
  const double last = static_cast<double>(by_time_.size() - 2);
  return f >= last ? by_time_.size() - 2 : static_cast<std::size_t>(f);  // clamped before the cast (t may be huge)
}

void Worldline::centre_at_coordinate_time(double t, Vec4& x, Vec4& u) const {
  if (t < start_time()) {
    x = samples_.front().x;
    x[0] = t;
    u = samples_.front().e.e[0];  // held at rest at the start
    return;
  }
  const std::size_t i = time_index(t);
  const double s = std::min(1.0, (t - by_time_[i].x[0]) / dt_);
  const TimeSample& a = by_time_[i];
  const TimeSample& b = by_time_[i + 1];
  double h00, h10, h01, h11;
  hermite(s, h00, h10, h01, h11);
  for (int m = 0; m < 4; ++m) {
    x[m] = h00 * a.x[m] + h10 * dt_ * a.dxdt[m] + h01 * b.x[m] + h11 * dt_ * b.dxdt[m];
    u[m] = h00 * a.u[m] + h10 * dt_ * a.dudt[m] + h01 * b.u[m] + h11 * dt_ * b.dudt[m];
  }
}

WorldlineEvent Worldline::at_coordinate_time(double t) const {
  if (t < samples_.front().x[0]) {
    // Held at rest at the start before release: same place, shifted in time.
    WorldlineEvent ev{samples_.front().x, samples_.front().e, 0.0};
    ev.x[0] = t;
    return ev;
  }
  return at_proper_time(proper_time_at(t));
}

double Worldline::scene_time(const Vec4& x) const {
  return std::visit([&](const auto& st) { return st.scene_from_trace(x)[0]; }, spacetime_.kinds());
}

std::vector<WorldlineEvent> Worldline::apocentres() const {
  auto radius = [&](const Vec4& x) {
    return std::visit(
        [&](const auto& st) {
          double t, r, phi;
          scene_polar(st, x, t, r, phi);
          return r;
        },
        spacetime_.kinds());
  };
  std::vector<WorldlineEvent> out;
  for (std::size_t i = 1; i + 1 < samples_.size(); ++i) {
    const double a = radius(samples_[i - 1].x), b = radius(samples_[i].x), c = radius(samples_[i + 1].x);
    if (!(b > a && b >= c)) continue;
    // Golden-section search for the maximum of r on the interpolant within
    // the bracket [i-1, i+1] of samples.
    double lo = (static_cast<double>(i) - 1) * dtau_, hi = (static_cast<double>(i) + 1) * dtau_;
    for (int it = 0; it < 80 && hi - lo > 1e-12; ++it) {
      const double m1 = lo + (hi - lo) * 0.381966011250105, m2 = lo + (hi - lo) * 0.618033988749895;
      if (radius(at_proper_time(m1).x) < radius(at_proper_time(m2).x))
        lo = m1;
      else
        hi = m2;
    }
    out.push_back(at_proper_time(0.5 * (lo + hi)));
  }
  return out;
}

void Worldline::bounds(double t0, double t1, Vec3& lo, Vec3& hi) const {
  if (t0 > t1) std::swap(t0, t1);
  // Chunks are whole runs of coordinate-time samples: an index, no search.
  const std::size_t i0 = t0 <= start_time() ? 0 : time_index(t0);
  const std::size_t i1 = t1 >= end_time() ? by_time_.size() - 1 : time_index(t1) + 1;
  lo = {1e300, 1e300, 1e300};
  hi = {-1e300, -1e300, -1e300};
  for (std::size_t c = i0 / kChunk; c <= std::min(i1 / kChunk, chunk_bounds_.size() - 1); ++c)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], chunk_bounds_[c][0][k]);
      hi[k] = std::max(hi[k], chunk_bounds_[c][1][k]);
    }
}

}  // namespace lc
