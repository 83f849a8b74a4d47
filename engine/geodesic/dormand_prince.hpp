#pragma once
// Dormand–Prince 5(4) Runge–Kutta with a PI step-size controller and the
// 4th-order continuous extension ("dense output").  Coefficients, error
// estimate, controller and dense output follow Hairer, Nørsett & Wanner,
// "Solving Ordinary Differential Equations I", 2nd ed., sec. II.4–II.5 and
// II.6 (DOPRI5), with Shampine's dense-output coefficients.  FSAL: six
// right-hand-side evaluations per accepted step.
//
// Header-only and templated on the state size, the right-hand side and the
// number of problems advanced at once (core/lanes.hpp: one in doubles, or
// one per vector lane, each with its own time, step size, controller and
// tolerances), so the metric inlines into the stages; nothing is allocated
// per step.  The arithmetic is written once for both: a lane computes what
// a single problem does.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "core/lanes.hpp"

namespace lc {

namespace detail {

// The controller's arithmetic is generic in T: double, or a GCC vector of
// doubles (one independent problem per lane, core/lanes.hpp).
// Bits<T>: the signed 64-bit integer type of T's shape.
template <class T>
struct Bits {
  using type = decltype(T{} < T{});  // a vector comparison's lane masks
};
template <>
struct Bits<double> {
  using type = std::int64_t;
};
template <class To, class From>
To convert_to(From x) {
  if constexpr (std::is_arithmetic_v<From>)
    return static_cast<To>(x);
  else
    return __builtin_convertvector(x, To);
}

// log2 and exp2 to ~1e-5 relative, for the step-size controller only: its
// factors are heuristics clamped to [0.1, 5], so libm's full precision
// (two pow calls per step: docs/performance.md, change 8) buys nothing.  Pure arithmetic, so the
// step sequence is the same on every machine.
// log2(x), x > 0 and finite: exponent from the bits, ln of the mantissa m
// in [1, 2) by the series 2 atanh((m - 1)/(m + 1)) to the 9th power.
template <class T>
T controller_log2(T x) {
  using I = typename Bits<T>::type;
  const I bits = std::bit_cast<I>(x);
  const I e = ((bits >> 52) & 0x7ff) - 1023;
  const T m = std::bit_cast<T>((bits & 0x000fffffffffffffLL) | 0x3ff0000000000000LL);
  const T t = (m - 1.0) / (m + 1.0), t2 = t * t;
  const T ln_m = 2.0 * t * (1.0 + t2 * (1.0 / 3.0 + t2 * (1.0 / 5.0 + t2 * (1.0 / 7.0 + t2 * (1.0 / 9.0)))));
  return convert_to<T>(e) + ln_m * 1.4426950408889634;
}
// 2^y for |y| < 1000: 2^floor(y) in the exponent bits, 2^f by Taylor to f^7.
template <class T>
T controller_exp2(T y) {
  using I = typename Bits<T>::type;
  I n = convert_to<I>(y);  // towards zero; then down to floor(y)
  if constexpr (std::is_arithmetic_v<T>) {
    if (static_cast<T>(n) > y) n -= 1;
  } else {
    n += convert_to<T>(n) > y;  // a true lane is -1
  }
  const T f = (y - convert_to<T>(n)) * 0.6931471805599453;
  const T p =
      1.0 + f * (1.0 + f * (0.5 + f * (1.0 / 6 + f * (1.0 / 24 + f * (1.0 / 120 + f * (1.0 / 720 + f * (1.0 / 5040)))))));
  return std::bit_cast<T>(std::bit_cast<I>(p) + (n << 52));
}

}  // namespace detail


struct StepControl {
  double rtol = 1e-9;
  double atol = 1e-9;
  double h_min = 1e-12;  // below this the integrator gives up (stiff or singular)
  double h_max = 1e30;
};

// One accepted step [t0, t0 + h] with its continuous extension.
template <std::size_t N>
struct DenseStep {
  using State = std::array<double, N>;
  double t0 = 0.0, h = 0.0;
  State r1{}, r2{}, r3{}, r4{}, r5{};

  // Component i at t in [t0, t0 + h] (4th-order accurate).
  double component(std::size_t i, double t) const {
    const double s = (t - t0) / h, s1 = 1.0 - s;
    return r1[i] + s * (r2[i] + s1 * (r3[i] + s * (r4[i] + s1 * r5[i])));
  }
  State at(double t) const {
    State y;
    for (std::size_t i = 0; i < N; ++i) y[i] = component(i, t);
    return y;
  }
  const State& start() const { return r1; }
};

// The Dormand–Prince 5(4) tableau (HNW II.5, Table 5.2), its error
// weights, Shampine's dense-output weights (HNW II.6) and the PI controller
// constants (HNW II.4, "beta = 0.04").
namespace dp5 {
inline constexpr double a21 = 1.0 / 5.0;
inline constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
inline constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
inline constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0, a54 = -212.0 / 729.0;
inline constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                        a65 = -5103.0 / 18656.0;
inline constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0, a75 = -2187.0 / 6784.0,
                        a76 = 11.0 / 84.0;
inline constexpr double c2 = 1.0 / 5.0, c3 = 3.0 / 10.0, c4 = 4.0 / 5.0, c5 = 8.0 / 9.0;
inline constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                        e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
inline constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                        d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                        d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
inline constexpr double beta = 0.04, expo1 = 0.2 - beta * 0.75, safe = 0.9, fac_min = 0.2, fac_max = 10.0;

// The stages of one attempt from (t, y) with slope k1 and step h: the
// 5th-order solution y7 and the slopes k3..k7 that the error estimate and
// dense output need.  T is double, or a vector of lanes (several
// independent problems at once, each with its own t and h).
template <class T, std::size_t N, class Rhs>
void stages(Rhs& rhs, T t, const std::array<T, N>& y, const std::array<T, N>& k1, T h, std::array<T, N>& y7,
            std::array<T, N>& k3, std::array<T, N>& k4, std::array<T, N>& k5, std::array<T, N>& k6,
            std::array<T, N>& k7) {
  std::array<T, N> ys, k2;
  for (std::size_t i = 0; i < N; ++i) ys[i] = y[i] + h * a21 * k1[i];
  rhs(t + c2 * h, ys, k2);
  for (std::size_t i = 0; i < N; ++i) ys[i] = y[i] + h * (a31 * k1[i] + a32 * k2[i]);
  rhs(t + c3 * h, ys, k3);
  for (std::size_t i = 0; i < N; ++i) ys[i] = y[i] + h * (a41 * k1[i] + a42 * k2[i] + a43 * k3[i]);
  rhs(t + c4 * h, ys, k4);
  for (std::size_t i = 0; i < N; ++i) ys[i] = y[i] + h * (a51 * k1[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
  rhs(t + c5 * h, ys, k5);
  for (std::size_t i = 0; i < N; ++i)
    ys[i] = y[i] + h * (a61 * k1[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
  rhs(t + h, ys, k6);
  for (std::size_t i = 0; i < N; ++i)
    y7[i] = y[i] + h * (a71 * k1[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
  rhs(t + h, y7, k7);
}

// Sum over components of (w e / sc)^2, the squared scaled error of the
// attempt (the norm is the square root of this over N).
// atol and rtol are T-wide: each lane may have its own tolerances.
template <class T, std::size_t N>
T error_sum(const std::array<T, N>& y, const std::array<T, N>& y7, const std::array<T, N>& k1,
            const std::array<T, N>& k3, const std::array<T, N>& k4, const std::array<T, N>& k5,
            const std::array<T, N>& k6, const std::array<T, N>& k7, T h, const std::array<double, N>& w, T atol,
            T rtol) {
  T err = h * 0.0;
  for (std::size_t i = 0; i < N; ++i) {
    if (w[i] == 0.0) continue;
    const T ei = h * (e1 * k1[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
    const T sc = atol + rtol * max_of(abs_of(y[i]), abs_of(y7[i]));
    const T q = w[i] * ei / sc;
    err += q * q;
  }
  return err;
}

// Shampine's continuous extension of an accepted attempt, as the
// coefficients r1..r5 of DenseStep (per component, T-wide).
template <class T, std::size_t N>
void dense_coefficients(const std::array<T, N>& y, const std::array<T, N>& y7, const std::array<T, N>& k1,
                        const std::array<T, N>& k3, const std::array<T, N>& k4, const std::array<T, N>& k5,
                        const std::array<T, N>& k6, const std::array<T, N>& k7, T h, std::array<T, N>& r1,
                        std::array<T, N>& r2, std::array<T, N>& r3, std::array<T, N>& r4, std::array<T, N>& r5) {
  for (std::size_t i = 0; i < N; ++i) {
    const T dy = y7[i] - y[i];
    const T bspl = h * k1[i] - dy;
    r1[i] = y[i];
    r2[i] = dy;
    r3[i] = bspl;
    r4[i] = dy - h * k7[i] - bspl;
    r5[i] = h * (d1 * k1[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] + d7 * k7[i]);
  }
}

// What the PI controller makes of an attempt's error norm err (err <= 1
// accepts), given log2 of the last accepted error: log2 err, the factor that
// divides h on acceptance (before clamping) and the one on rejection.  T as
// in detail::controller_log2: the lanes work out all their factors at once.
template <class T>
struct ControllerFactors {
  T err, log2_err, accept, reject;
};
template <class T>
ControllerFactors<T> controller_factors(T err, T log2_err_old) {
  const T big = T{} + 1e10;
  err = err == err && err < T{} + 1e300 ? err : big;  // a stage left the domain: shrink hard
  // err^expo1 and err_old^beta through one log2 each; err is at least
  // 1e-10 here so the logarithms are finite.
  const T log_err = detail::controller_log2(max_of(err, T{} + 1e-10));
  return {err, log_err, detail::controller_exp2(expo1 * log_err - beta * log2_err_old) / safe,
          detail::controller_exp2(expo1 * log_err) / safe};
}

// The PI step-size controller of one problem.
struct Controller {
  double log2_err_old = -13.287712379549449;  // log2(1e-4)
  bool rejected_last = false;

  void reset() {
    log2_err_old = detail::controller_log2(1e-4);
    rejected_last = false;
  }
  // Inputs: the attempt's error norm (err <= 1 accepts) and step h; output:
  // whether it is accepted, and the next step to try.
  bool decide(double err, double h, const StepControl& c, double& h_next) {
    return decide(controller_factors(err, log2_err_old), h, c, h_next);
  }
  // The same with the factors worked out already.
  bool decide(const ControllerFactors<double>& f, double h, const StepControl& c, double& h_next) {
    if (f.err <= 1.0) {
      const double fac = std::clamp(f.accept, 1.0 / fac_max, 1.0 / fac_min);
      double h_new = h / fac;
      if (std::abs(h_new) > c.h_max) h_new = std::copysign(c.h_max, h);
      if (rejected_last) h_new = std::copysign(std::min(std::abs(h_new), std::abs(h)), h);
      // log2(max(err, 1e-4)), log2 being monotone.
      log2_err_old = std::max(f.log2_err, detail::controller_log2(1e-4));
      rejected_last = false;
      h_next = h_new;
      return true;
    }
    h_next = h / std::min(1.0 / fac_min, f.reject);
    rejected_last = true;
    return false;
  }
};

}  // namespace dp5

// W problems of N components at once (core/lanes.hpp: W = 1 is one problem
// in doubles).  Rhs: void(T t, const std::array<T, N>& y, std::array<T, N>&
// dydt) with T = Lanes<W>; it may hold per-lane constants the caller sets
// before start().  Weights: per-component factor on the error estimate (0
// excludes a component from step control).
template <std::size_t N, class Rhs, int W = 1>
class DormandPrince5 {
 public:
  using T = Lanes<W>;
  using Vector = std::array<T, N>;
  using State = std::array<double, N>;

  DormandPrince5(Rhs rhs, const StepControl& control, const State& weights) : rhs_(rhs), c_(control), w_(weights) {
    atol_ = T{} + c_.atol;
    rtol_ = T{} + c_.rtol;
  }

  // Lane i starts at y0 with slope k0 and first trial step h (its sign gives
  // the direction), at the control's tolerances.
  void start(int i, const State& y0, const State& k0, double h) {
    put(y_, i, y0);
    put(k1_, i, k0);
    t_[i] = 0.0;
    h_[i] = h;
    set_lane(atol_, i, c_.atol);
    set_lane(rtol_, i, c_.rtol);
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
    set_lane(atol_, i, get_lane(atol_, i) * factor);
    set_lane(rtol_, i, get_lane(rtol_, i) * factor);
  }

  double t(int i) const { return t_[i]; }
  State y(int i) const {
    State s;
    for (std::size_t j = 0; j < N; ++j) s[j] = get_lane(y_[j], i);
    return s;
  }
  // Component j of lane i's state and of its slope there.
  double y(int i, std::size_t j) const { return get_lane(y_[j], i); }
  double slope(int i, std::size_t j) const { return get_lane(k1_[j], i); }

  // One attempt on every live lane.  A lane whose step fell below h_min
  // calls gave_up(i); an accepted step advances the lane and calls
  // accepted(i, dense) (the callbacks may start() or stop() lane i); a
  // rejected one only shrinks the lane's step.  Returns false when no lane
  // is live.
  template <class Accepted, class GaveUp>
  bool attempt(Accepted&& accepted, GaveUp&& gave_up) {
    bool any = false;
    T tv{}, hv{};
    for (int i = 0; i < W; ++i) {
      any = any || live_[i];
      set_lane(tv, i, t_[i]);
      set_lane(hv, i, live_[i] ? h_[i] : 0.0);
    }
    if (!any) return false;
    dp5::stages(rhs_, tv, y_, k1_, hv, y7_, k3_, k4_, k5_, k6_, k7_);
    const T e2 = dp5::error_sum(y_, y7_, k1_, k3_, k4_, k5_, k6_, k7_, hv, w_, atol_, rtol_);
    dp5::dense_coefficients(y_, y7_, k1_, k3_, k4_, k5_, k6_, k7_, hv, r1_, r2_, r3_, r4_, r5_);
    // The controllers' logarithms and powers for all lanes at once (a
    // tenth of a dihole frame when each lane worked out its own).
    T log2_err_old{};
    for (int i = 0; i < W; ++i) set_lane(log2_err_old, i, control_[i].log2_err_old);
    const dp5::ControllerFactors<T> f = dp5::controller_factors(sqrt_of(e2 / static_cast<double>(N)), log2_err_old);
    for (int i = 0; i < W; ++i) {
      if (!live_[i]) continue;
      const double h = h_[i];
      if (std::abs(h) < c_.h_min) {
        gave_up(i);
        continue;
      }
      StepControl c = c_;
      c.atol = get_lane(atol_, i);
      c.rtol = get_lane(rtol_, i);
      double h_next = h;
      if (!control_[i].decide({get_lane(f.err, i), get_lane(f.log2_err, i), get_lane(f.accept, i), get_lane(f.reject, i)},
                              h, c, h_next)) {
        h_[i] = h_next;
        continue;
      }
      step_.t0 = t_[i];
      step_.h = h;
      for (std::size_t j = 0; j < N; ++j) {
        step_.r1[j] = get_lane(r1_[j], i);
        step_.r2[j] = get_lane(r2_[j], i);
        step_.r3[j] = get_lane(r3_[j], i);
        step_.r4[j] = get_lane(r4_[j], i);
        step_.r5[j] = get_lane(r5_[j], i);
        set_lane(y_[j], i, get_lane(y7_[j], i));
        set_lane(k1_[j], i, get_lane(k7_[j], i));
      }
      t_[i] += h;
      h_[i] = h_next;
      accepted(i, step_);
    }
    return true;
  }

  // One problem (W = 1): starts at (t, y) with a first trial step h.
  void reset(double t, const State& y, double h)
    requires(W == 1)
  {
    State k;
    rhs_(t, y, k);
    start(0, y, k, h);
    t_[0] = t;
  }
  // One problem (W = 1): advances by one accepted step and fills `dense`;
  // false when the step size fell below h_min (the integrator gives up).
  bool step(DenseStep<N>& dense)
    requires(W == 1)
  {
    bool done = false, failed = false;
    while (!done && !failed)
      attempt(
          [&](int, const DenseStep<N>& s) {
            dense = s;
            done = true;
          },
          [&](int) { failed = true; });
    if (failed) live_[0] = false;
    return done;
  }
  const State& y() const
    requires(W == 1)
  {
    return y_;
  }
  const State& dydt() const
    requires(W == 1)
  {
    return k1_;
  }
  double t() const
    requires(W == 1)
  {
    return t_[0];
  }
  double step_size() const
    requires(W == 1)
  {
    return h_[0];
  }

 private:
  static void put(Vector& v, int i, const State& s) {
    for (std::size_t j = 0; j < N; ++j) set_lane(v[j], i, s[j]);
  }

  Rhs rhs_;
  StepControl c_;
  State w_;
  Vector y_{}, k1_{}, y7_{}, k3_{}, k4_{}, k5_{}, k6_{}, k7_{}, r1_{}, r2_{}, r3_{}, r4_{}, r5_{};
  T atol_{}, rtol_{};
  std::array<double, W> t_{}, h_{};
  std::array<dp5::Controller, W> control_{};
  std::array<bool, W> live_{};
  DenseStep<N> step_;
};

}  // namespace lc
