#pragma once
// Locating where a ray crosses a surface inside one integration step, from
// the step's dense output, so surfaces never force small steps.  Uses the
// Illinois variant of regula falsi (Dowell & Jarratt, BIT 11, 1971):
// bracketing, superlinear, and robust where the function is flat.

#include <cmath>

#include "geodesic/dormand_prince.hpp"

namespace lc {

// g(state) changes sign between parameters a and b inside the step (ga at a,
// gb at b).  Returns the parameter of the crossing to within `tol` in g or
// in the parameter.
template <std::size_t N, class G>
double locate_crossing(const DenseStep<N>& step, G&& g, double a, double b, double ga, double gb,
                       double tol = 1e-13) {
  int side = 0;
  for (int it = 0; it < 60; ++it) {
    const double t = (a * gb - b * ga) / (gb - ga);
    const double gt = g(step.at(t));
    if (std::abs(gt) <= tol || std::abs(b - a) <= tol * (1.0 + std::abs(t))) return t;
    if ((gt > 0.0) == (gb > 0.0)) {
      b = t;
      gb = gt;
      if (side == -1) ga *= 0.5;
      side = -1;
    } else {
      a = t;
      ga = gt;
      if (side == 1) gb *= 0.5;
      side = 1;
    }
  }
  return (a * gb - b * ga) / (gb - ga);
}

// The same over the whole step (g0 at t0, g1 at t0 + h).
template <std::size_t N, class G>
double locate_crossing(const DenseStep<N>& step, G&& g, double g0, double g1, double tol = 1e-13) {
  return locate_crossing(step, g, step.t0, step.t0 + step.h, g0, g1, tol);
}

}  // namespace lc
