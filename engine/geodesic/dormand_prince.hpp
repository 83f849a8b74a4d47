#pragma once
// Dormand–Prince 5(4) Runge–Kutta with a PI step-size controller and the
// 4th-order continuous extension ("dense output").  Coefficients, error
// estimate, controller and dense output follow Hairer, Nørsett & Wanner,
// "Solving Ordinary Differential Equations I", 2nd ed., sec. II.4–II.5 and
// II.6 (DOPRI5), with Shampine's dense-output coefficients.  FSAL: six
// right-hand-side evaluations per accepted step.
//
// Header-only and templated on the state size and the right-hand side so the
// metric inlines into the stages; nothing is allocated per step.

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace lc {

namespace detail {

// log2 and exp2 to ~1e-5 relative, for the step-size controller only: its
// factors are heuristics clamped to [0.1, 5], so libm's full precision
// (two pow calls, ~9% of a step) buys nothing.  Pure arithmetic, so the
// step sequence is the same on every machine.
// log2(x), x > 0 and finite: exponent from the bits, ln of the mantissa m
// in [1, 2) by the series 2 atanh((m - 1)/(m + 1)) to the 9th power.
inline double controller_log2(double x) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  const double m = std::bit_cast<double>((bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL);
  const double t = (m - 1.0) / (m + 1.0), t2 = t * t;
  const double ln_m = 2.0 * t * (1.0 + t2 * (1.0 / 3.0 + t2 * (1.0 / 5.0 + t2 * (1.0 / 7.0 + t2 * (1.0 / 9.0)))));
  return e + ln_m * 1.4426950408889634;
}
// 2^y for |y| < 1000: 2^floor(y) in the exponent bits, 2^f by Taylor to f^7.
inline double controller_exp2(double y) {
  const double n = std::floor(y);
  const double f = (y - n) * 0.6931471805599453;
  const double p =
      1.0 + f * (1.0 + f * (0.5 + f * (1.0 / 6 + f * (1.0 / 24 + f * (1.0 / 120 + f * (1.0 / 720 + f * (1.0 / 5040)))))));
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(p) + (static_cast<std::uint64_t>(static_cast<std::int64_t>(n)) << 52));
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

// Rhs: void(double t, const State& y, State& dydt).  Weights: per-component
// factor on the error estimate (0 excludes a component from step control).
template <std::size_t N, class Rhs>
class DormandPrince5 {
 public:
  using State = std::array<double, N>;

  DormandPrince5(Rhs rhs, StepControl control, State weights) : rhs_(rhs), c_(control), w_(weights) {}

  // Starts at (t, y) with a first trial step h (sign gives the direction).
  void reset(double t, const State& y, double h) {
    t_ = t;
    y_ = y;
    h_ = h;
    log2_err_old_ = detail::controller_log2(1e-4);
    rhs_(t_, y_, k1_);
    rejected_last_ = false;
  }

  // New tolerances from the next step on (the state and step size are kept).
  void set_control(const StepControl& control) { c_ = control; }

  double t() const { return t_; }
  const State& y() const { return y_; }
  const State& dydt() const { return k1_; }
  double step_size() const { return h_; }
  long rejected() const { return rejected_; }

  // Advances by one accepted step and fills `dense`.  Returns false when the
  // step size falls below h_min (the integrator gives up).
  bool step(DenseStep<N>& dense) {
    constexpr double a21 = 1.0 / 5.0;
    constexpr double a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
    constexpr double a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
    constexpr double a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                     a54 = -212.0 / 729.0;
    constexpr double a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0, a64 = 49.0 / 176.0,
                     a65 = -5103.0 / 18656.0;
    constexpr double a71 = 35.0 / 384.0, a73 = 500.0 / 1113.0, a74 = 125.0 / 192.0, a75 = -2187.0 / 6784.0,
                     a76 = 11.0 / 84.0;
    constexpr double c2 = 1.0 / 5.0, c3 = 3.0 / 10.0, c4 = 4.0 / 5.0, c5 = 8.0 / 9.0;
    constexpr double e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0, e5 = -17253.0 / 339200.0,
                     e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;
    constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                     d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                     d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
    // PI controller constants (HNW II.4, "beta = 0.04").
    constexpr double beta = 0.04, expo1 = 0.2 - beta * 0.75, safe = 0.9, fac_min = 0.2, fac_max = 10.0;

    State y2, y3, y4, y5, y6, y7, k2, k3, k4, k5, k6, k7;
    for (;;) {
      const double h = h_;
      if (std::abs(h) < c_.h_min) return false;
      for (std::size_t i = 0; i < N; ++i) y2[i] = y_[i] + h * a21 * k1_[i];
      rhs_(t_ + c2 * h, y2, k2);
      for (std::size_t i = 0; i < N; ++i) y3[i] = y_[i] + h * (a31 * k1_[i] + a32 * k2[i]);
      rhs_(t_ + c3 * h, y3, k3);
      for (std::size_t i = 0; i < N; ++i) y4[i] = y_[i] + h * (a41 * k1_[i] + a42 * k2[i] + a43 * k3[i]);
      rhs_(t_ + c4 * h, y4, k4);
      for (std::size_t i = 0; i < N; ++i)
        y5[i] = y_[i] + h * (a51 * k1_[i] + a52 * k2[i] + a53 * k3[i] + a54 * k4[i]);
      rhs_(t_ + c5 * h, y5, k5);
      for (std::size_t i = 0; i < N; ++i)
        y6[i] = y_[i] + h * (a61 * k1_[i] + a62 * k2[i] + a63 * k3[i] + a64 * k4[i] + a65 * k5[i]);
      rhs_(t_ + h, y6, k6);
      for (std::size_t i = 0; i < N; ++i)
        y7[i] = y_[i] + h * (a71 * k1_[i] + a73 * k3[i] + a74 * k4[i] + a75 * k5[i] + a76 * k6[i]);
      rhs_(t_ + h, y7, k7);

      double err = 0.0;
      for (std::size_t i = 0; i < N; ++i) {
        if (w_[i] == 0.0) continue;
        const double ei =
            h * (e1 * k1_[i] + e3 * k3[i] + e4 * k4[i] + e5 * k5[i] + e6 * k6[i] + e7 * k7[i]);
        const double sc = c_.atol + c_.rtol * std::max(std::abs(y_[i]), std::abs(y7[i]));
        const double q = w_[i] * ei / sc;
        err += q * q;
      }
      err = std::sqrt(err / static_cast<double>(N));
      if (!std::isfinite(err)) err = 1e10;  // a stage left the domain: shrink hard

      // err^expo1 and err_old^beta (HNW's PI controller) through one log2
      // each; err is at least 1e-10 here so the logarithms are finite.
      const double log_err = detail::controller_log2(std::max(err, 1e-10));
      const double fac11 = detail::controller_exp2(expo1 * log_err);
      if (err <= 1.0) {
        double fac = detail::controller_exp2(expo1 * log_err - beta * log2_err_old_) / safe;
        fac = std::clamp(fac, 1.0 / fac_max, 1.0 / fac_min);
        double h_new = h / fac;
        if (std::abs(h_new) > c_.h_max) h_new = std::copysign(c_.h_max, h);
        if (rejected_last_) h_new = std::copysign(std::min(std::abs(h_new), std::abs(h)), h);
        log2_err_old_ = detail::controller_log2(std::max(err, 1e-4));
        rejected_last_ = false;

        dense.t0 = t_;
        dense.h = h;
        for (std::size_t i = 0; i < N; ++i) {
          const double dy = y7[i] - y_[i];
          const double bspl = h * k1_[i] - dy;
          dense.r1[i] = y_[i];
          dense.r2[i] = dy;
          dense.r3[i] = bspl;
          dense.r4[i] = dy - h * k7[i] - bspl;
          dense.r5[i] = h * (d1 * k1_[i] + d3 * k3[i] + d4 * k4[i] + d5 * k5[i] + d6 * k6[i] + d7 * k7[i]);
        }
        t_ += h;
        y_ = y7;
        k1_ = k7;
        h_ = h_new;
        return true;
      }
      h_ = h / std::min(1.0 / fac_min, fac11 / safe);
      rejected_last_ = true;
      ++rejected_;
    }
  }

 private:
  Rhs rhs_;
  StepControl c_;
  State w_;
  double t_ = 0.0, h_ = 0.0, log2_err_old_ = -13.287712379549449;  // log2(1e-4)
  State y_{}, k1_{};
  bool rejected_last_ = false;
  long rejected_ = 0;
};

}  // namespace lc
