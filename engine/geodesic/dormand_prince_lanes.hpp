#pragma once
// Dormand–Prince 5(4) on lane_count independent 8-component problems at
// once (one per vector lane, lanes.hpp's LaneVec): the arithmetic of
// dormand_prince.hpp's dp5 pieces on vectors, and per lane its own time,
// step size, PI controller and tolerances.  The ray drivers of
// render/trace_batch.hpp start and stop problems in lanes as rays begin and end.

#include <array>
#include <cmath>

#include "geodesic/dormand_prince.hpp"
#include "geodesic/lanes.hpp"

namespace lc {

template <class Rhs4>
class DormandPrince5Lanes {
 public:
  using Lanes = std::array<LaneVec, 8>;
  using State = std::array<double, 8>;

  // rhs: the right-hand side on lanes (it may hold per-lane constants the
  // caller sets before start()); weights as for DormandPrince5.
  DormandPrince5Lanes(const Rhs4& rhs, const StepControl& control, const State& weights)
      : rhs_(rhs), c_(control), w_(weights) {
    atol_ = LaneVec{} + c_.atol;
    rtol_ = LaneVec{} + c_.rtol;
  }

  // Lane i starts at y0 with slope k0 and first trial step h, at the
  // control's tolerances.
  void start(int i, const State& y0, const State& k0, double h) {
    put(y_, i, y0);
    put(k1_, i, k0);
    t_[i] = 0.0;
    h_[i] = h;
    atol_[i] = c_.atol;
    rtol_[i] = c_.rtol;
    control_[i].reset();
    live_[i] = true;
  }
  // Lane i idles at a state whose right-hand side is finite (k0 its slope).
  void stop(int i, const State& idle, const State& k0) {
    put(y_, i, idle);
    put(k1_, i, k0);
    live_[i] = false;
  }
  // Lane i's tolerances times `factor` from its next attempt on.
  void relax(int i, double factor) {
    atol_[i] *= factor;
    rtol_[i] *= factor;
  }

  double t(int i) const { return t_[i]; }
  State y(int i) const {
    State s;
    for (int j = 0; j < 8; ++j) s[j] = y_[j][i];
    return s;
  }
  // Component j of lane i's state and of its slope there.
  double y(int i, int j) const { return y_[j][i]; }
  double slope(int i, int j) const { return k1_[j][i]; }

  // One attempt on every live lane.  A lane whose step fell below h_min
  // calls gave_up(i); an accepted step advances the lane and calls
  // accepted(i, dense) (the callbacks may start() or stop() lane i); a
  // rejected one only shrinks the lane's step.  Returns false when no lane
  // is live.
  template <class Accepted, class GaveUp>
  bool attempt(Accepted&& accepted, GaveUp&& gave_up) {
    bool any = false;
    LaneVec tv{}, hv{};
    for (int i = 0; i < lane_count; ++i) {
      any = any || live_[i];
      tv[i] = t_[i];
      hv[i] = live_[i] ? h_[i] : 0.0;
    }
    if (!any) return false;
    dp5::stages(rhs_, tv, y_, k1_, hv, y7_, k3_, k4_, k5_, k6_, k7_);
    const LaneVec e2 = dp5::error_sum(y_, y7_, k1_, k3_, k4_, k5_, k6_, k7_, hv, w_, atol_, rtol_);
    dp5::dense_coefficients(y_, y7_, k1_, k3_, k4_, k5_, k6_, k7_, hv, r1_, r2_, r3_, r4_, r5_);
    // The controllers' logarithms and powers for all lanes at once (a
    // tenth of a dihole frame when each lane worked out its own).
    LaneVec log2_err_old{};
    for (int i = 0; i < lane_count; ++i) log2_err_old[i] = control_[i].log2_err_old;
    const dp5::ControllerFactors<LaneVec> f = dp5::controller_factors(sqrt_of(e2 / 8.0), log2_err_old);
    for (int i = 0; i < lane_count; ++i) {
      if (!live_[i]) continue;
      const double h = h_[i];
      if (std::abs(h) < c_.h_min) {
        gave_up(i);
        continue;
      }
      StepControl c = c_;
      c.atol = atol_[i];
      c.rtol = rtol_[i];
      double h_next = h;
      if (!control_[i].decide({f.err[i], f.log2_err[i], f.accept[i], f.reject[i]}, h, c, h_next)) {
        h_[i] = h_next;
        continue;
      }
      step_.t0 = t_[i];
      step_.h = h;
      for (int j = 0; j < 8; ++j) {
        step_.r1[j] = r1_[j][i];
        step_.r2[j] = r2_[j][i];
        step_.r3[j] = r3_[j][i];
        step_.r4[j] = r4_[j][i];
        step_.r5[j] = r5_[j][i];
        y_[j][i] = y7_[j][i];
        k1_[j][i] = k7_[j][i];
      }
      t_[i] += h;
      h_[i] = h_next;
      accepted(i, step_);
    }
    return true;
  }

 private:
  static void put(Lanes& v, int i, const State& s) {
    for (int j = 0; j < 8; ++j) v[j][i] = s[j];
  }

  const Rhs4& rhs_;
  StepControl c_;
  State w_;
  Lanes y_{}, k1_{}, y7_{}, k3_{}, k4_{}, k5_{}, k6_{}, k7_{}, r1_{}, r2_{}, r3_{}, r4_{}, r5_{};
  LaneVec atol_{}, rtol_{};
  std::array<double, lane_count> t_{}, h_{};
  std::array<dp5::Controller, lane_count> control_{};
  std::array<bool, lane_count> live_{};
  DenseStep<8> step_;
};

}  // namespace lc
