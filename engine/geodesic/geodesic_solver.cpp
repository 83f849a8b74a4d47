#include "geodesic/geodesic_solver.hpp"

#include <cmath>
#include <memory>
#include <mutex>
#include <optional>
#include <string_view>
#include <stdexcept>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <fmt/format.h>

#include "geodesic/christoffel.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace {

// State layout: x^mu (4), p_mu (4), lambda (1), then 16 tetrad components.
constexpr int base_dim = 9;

template <class S>
struct System {
  const S& st;
  double orientation;  // +1 integrate to the future, -1 to the past
  StopParameter param;
  bool transport;
};

// d/ds of the state, where s is the stop parameter (covered amount, >= 0) and
// mu the integration parameter with tangent dx/dmu = g^{-1} p.
template <class S>
int rhs(double, const double y[], double dyds[], void* params) {
  const auto& sys = *static_cast<const System<S>*>(params);
  const Vec4 x = {y[0], y[1], y[2], y[3]};
  const Vec4 p = {y[4], y[5], y[6], y[7]};
  Vec4 dx, dp;
  sys.st.hamiltonian_rhs(x, p, dx, dp);
  double w = 1.0;  // ds/dmu
  if (sys.param == StopParameter::coordinate_time) {
    w = sys.orientation * dot(sys.st.scene_time_gradient(x), dx);
    if (!(w > 0.0)) return GSL_EBADFUNC;  // scene time no longer runs along the curve
  }
  const double inv_w = 1.0 / w;
  for (int i = 0; i < 4; ++i) {
    dyds[i] = dx[i] * inv_w;
    dyds[4 + i] = dp[i] * inv_w;
  }
  dyds[8] = sys.orientation * inv_w;
  if (sys.transport) {
    const Christoffel G = christoffel(sys.st, x);
    for (int a = 0; a < 4; ++a) {
      const Vec4 e = {y[base_dim + 4 * a], y[base_dim + 4 * a + 1], y[base_dim + 4 * a + 2], y[base_dim + 4 * a + 3]};
      const Vec4 de = transport_rate(G, dx, e);
      for (int m = 0; m < 4; ++m) dyds[base_dim + 4 * a + m] = de[m] * inv_w;
    }
  }
  for (int i = 0; i < (sys.transport ? base_dim + 16 : base_dim); ++i)
    if (!std::isfinite(dyds[i])) return GSL_EBADFUNC;
  return GSL_SUCCESS;
}

template <class S>
GeodesicSample sample_of(const S& st, const double y[], double orientation, bool transport) {
  GeodesicSample s{};
  s.lambda = y[8];
  s.x = {y[0], y[1], y[2], y[3]};
  const Vec4 p = {y[4], y[5], y[6], y[7]};
  Vec4 dx, dp;
  st.hamiltonian_rhs(s.x, p, dx, dp);
  s.u = orientation * dx;
  s.hamiltonian = 0.5 * dot(p, dx);
  if (transport)
    for (int a = 0; a < 4; ++a)
      for (int m = 0; m < 4; ++m) s.e[a][m] = y[base_dim + 4 * a + m];
  return s;
}

// The slope of the state (x, p) as S::flight reads it, evaluated only if
// it is read (most steps are well inside the escape radius).
template <class S>
struct LazySlope {
  const S& st;
  const std::array<double, 8>& y;
  mutable std::optional<std::array<double, 8>> dy;
  double operator()(std::size_t j) const {
    if (!dy) {
      Vec4 dx, dp;
      st.hamiltonian_rhs({y[0], y[1], y[2], y[3]}, {y[4], y[5], y[6], y[7]}, dx, dp);
      dy = std::array<double, 8>{dx[0], dx[1], dx[2], dx[3], dp[0], dp[1], dp[2], dp[3]};
    }
    return (*dy)[j];
  }
};

struct GslDeleter {
  void operator()(gsl_odeiv2_step* p) const { gsl_odeiv2_step_free(p); }
  void operator()(gsl_odeiv2_control* p) const { gsl_odeiv2_control_free(p); }
  void operator()(gsl_odeiv2_evolve* p) const { gsl_odeiv2_evolve_free(p); }
};

template <class S>
GeodesicPath solve(const S& st, const GeodesicProblem& pb) {
  const double orientation = pb.direction == TimeDirection::future ? 1.0 : -1.0;
  const bool transport = pb.tetrad.has_value();
  const int dim = transport ? base_dim + 16 : base_dim;
  std::vector<double> y(dim, 0.0);
  // Integration tangent dx/dmu = orientation * u0; p = g dx/dmu.
  const Vec4 p0 = mat_vec(st.metric(pb.x0), orientation * pb.u0);
  for (int i = 0; i < 4; ++i) {
    y[i] = pb.x0[i];
    y[4 + i] = p0[i];
  }
  if (transport)
    for (int a = 0; a < 4; ++a)
      for (int m = 0; m < 4; ++m) y[base_dim + 4 * a + m] = pb.tetrad->e[a][m];

  System<S> sys{st, orientation, pb.stop_parameter, transport};
  gsl_odeiv2_system gsys{&rhs<S>, nullptr, static_cast<size_t>(dim), &sys};
  const gsl_odeiv2_step_type* type = pb.stepper == GslStepper::rk8pd ? gsl_odeiv2_step_rk8pd : gsl_odeiv2_step_rkf45;
  std::unique_ptr<gsl_odeiv2_step, GslDeleter> stepper(gsl_odeiv2_step_alloc(type, dim));
  std::unique_ptr<gsl_odeiv2_control, GslDeleter> control(gsl_odeiv2_control_y_new(pb.tolerance, pb.tolerance));
  std::unique_ptr<gsl_odeiv2_evolve, GslDeleter> evolve(gsl_odeiv2_evolve_alloc(dim));

  GeodesicPath path;
  path.samples.reserve(pb.samples);
  path.samples.push_back(sample_of(st, y.data(), orientation, transport));
  const double h0 = path.samples[0].hamiltonian;

  double s = 0.0;
  double h = 1e-3 * std::min(1.0, pb.stop_value);
  const FlightRadii radii{1e300, pb.escape_radius * pb.escape_radius};
  bool stopped = false;
  for (int k = 1; k < pb.samples && !stopped; ++k) {
    const double target = k == pb.samples - 1 ? pb.stop_value : pb.stop_value * k / (pb.samples - 1);
    while (s < target) {
      if (path.steps >= pb.max_steps) {
        path.reason = StopReason::step_limit;
        stopped = true;
        break;
      }
      const int status = gsl_odeiv2_evolve_apply(evolve.get(), control.get(), stepper.get(), &gsys, &s, target, &h,
                                                 y.data());
      ++path.steps;
      const Vec4 x = {y[0], y[1], y[2], y[3]};
      if (status != GSL_SUCCESS) {
        // Coordinate time stops running only at a horizon (BL t is a time
        // function outside it), so a refused evaluation there is a capture.
        const bool at_horizon =
            st.captured(x) || (status == GSL_EBADFUNC && pb.stop_parameter == StopParameter::coordinate_time);
        path.reason = at_horizon ? StopReason::horizon : StopReason::gave_up;
        stopped = true;
        break;
      }
      if (st.captured(x)) {
        path.reason = StopReason::horizon;
        stopped = true;
        break;
      }
      // The renderer's far-end rule (S::flight), with the slope in the
      // integration parameter (only its direction matters).
      const std::array<double, 8> state = {y[0], y[1], y[2], y[3], y[4], y[5], y[6], y[7]};
      if (const Flight f = st.flight(StateComponents{&state}, LazySlope<S>{st, state}, radii); f.escaped) {
        path.reason = StopReason::escaped;
        path.end = S::ends[f.end].name;
        stopped = true;
        break;
      }
    }
    path.samples.push_back(sample_of(st, y.data(), orientation, transport));
    const double drift = std::abs(path.samples.back().hamiltonian - h0) * 2.0;
    path.max_constraint_drift = std::max(path.max_constraint_drift, drift);
  }
  return path;
}

}  // namespace

GeodesicPath solve_geodesic(const GeodesicProblem& pb) {
  if (pb.samples < 2) throw std::invalid_argument("geodesic: samples must be at least 2");
  if (!(pb.stop_value > 0.0) || !std::isfinite(pb.stop_value))
    throw std::invalid_argument("geodesic: the stop value must be a positive number");
  if (pb.kind == CurveKind::null && pb.stop_parameter == StopParameter::proper_time)
    throw std::invalid_argument("geodesic: a null curve has no proper time; stop on affine or coordinate time");
  return std::visit(
      [&](const auto& st) {
        if (const std::string_view why = st.why_no_observer(pb.x0); !why.empty())
          throw std::invalid_argument(fmt::format("geodesic: the start lies {}", why));
        // GSL's default handler aborts the process; errors are handled by
        // status codes here.  The handler is process-wide, so switch it off once.
        static std::once_flag quiet;
        std::call_once(quiet, [] { gsl_set_error_handler_off(); });
        return solve(st, pb);
      },
      pb.spacetime.kinds());
}

}  // namespace lc
