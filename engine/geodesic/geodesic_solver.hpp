#pragma once
// Reference geodesic solver on GSL's odeiv2 (embedded Runge–Kutta–Prince–
// Dormand 8(9) by default, Runge–Kutta–Fehlberg 4(5) as the paper used): null
// or timelike curves, optionally parallel-transporting a tetrad, sampled at
// uniform steps of the chosen stop parameter.  Serves wherever precision
// matters more than speed: worldlines of observers and objects (once per
// shot), `lightcone geodesic`, and tight-tolerance reference renders.

#include <optional>
#include <string_view>
#include <vector>

#include "core/constants.hpp"
#include "geodesic/stop_reason.hpp"
#include "eye/tetrad.hpp"
#include "spacetime/spacetime_spec.hpp"

namespace lc {

enum class CurveKind { null, timelike };
enum class StopParameter { affine, proper_time, coordinate_time };
// TimeDirection: spacetime/chart.hpp.
enum class GslStepper { rk8pd, rkf45 };

struct GeodesicProblem {
  Spacetime spacetime;  // Minkowski unless set
  CurveKind kind = CurveKind::null;
  Vec4 x0{};  // start event, trace coordinates
  // Future-directed tangent at the start (trace coordinates): a null vector,
  // or the unit 4-velocity of a timelike curve.
  Vec4 u0{};
  TimeDirection direction = TimeDirection::future;
  std::optional<Tetrad> tetrad;  // transported along the curve when set
  StopParameter stop_parameter = StopParameter::affine;
  double stop_value = 1.0;  // amount of the stop parameter to cover (> 0)
  int samples = 2;          // rows at uniform steps, including both ends (>= 2)
  double escape_radius = default_escape_radius;
  double tolerance = 1e-12;  // GSL absolute and relative error bound
  long max_steps = 1000000;
  GslStepper stepper = GslStepper::rk8pd;
};

struct GeodesicSample {
  double lambda;             // affine parameter or proper time, signed (< 0 into the past)
  Vec4 x;                    // trace coordinates
  Vec4 u;                    // dx/dlambda, trace coordinates (future-directed for timelike)
  std::array<Vec4, 4> e{};   // transported tetrad (when requested)
  double hamiltonian;        // 1/2 g(u, u): 0 for null, -1/2 for timelike
};

struct GeodesicPath {
  std::vector<GeodesicSample> samples;
  StopReason reason = StopReason::reached;
  // The spacetime's end (its name in S::ends) an escaped curve reached;
  // empty otherwise.
  std::string_view end;
  long steps = 0;
  double max_constraint_drift = 0.0;  // max |g(u,u) - g(u0,u0)| over the samples
};

// Integrates the problem.  Throws std::invalid_argument for an inconsistent
// problem (a start where no observer may stand, such as inside a horizon;
// samples < 2, stop_value <= 0, proper time for a null curve).  Samples past an early stop are not produced: the last
// sample is then the stop point itself.
GeodesicPath solve_geodesic(const GeodesicProblem& problem);

}  // namespace lc
