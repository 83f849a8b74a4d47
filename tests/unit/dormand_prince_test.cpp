// The hand-written Dormand–Prince 5(4) against problems with exact solutions:
// it must meet its tolerance, converge at 5th order as the tolerance falls,
// and its dense output must be accurate between steps (4th order).

#include <gtest/gtest.h>

#include <cmath>

#include "geodesic/dormand_prince.hpp"

namespace lc {
namespace {

// Harmonic oscillator y'' = -y: y = cos t, y' = -sin t.
struct Oscillator {
  void operator()(double, const std::array<double, 2>& y, std::array<double, 2>& d) const { d = {y[1], -y[0]}; }
};

double global_error(double tol, long* steps = nullptr) {
  DormandPrince5<2, Oscillator> dp(Oscillator{}, StepControl{tol, tol, 1e-14, 1e30}, {1.0, 1.0});
  dp.reset(0.0, {1.0, 0.0}, 0.01);
  DenseStep<2> s;
  long n = 0;
  double err = 0.0;
  while (dp.t() < 20.0) {
    EXPECT_TRUE(dp.step(s));
    ++n;
    err = std::max(err, std::abs(dp.y()[0] - std::cos(dp.t())));
  }
  if (steps) *steps = n;
  return err;
}

TEST(DormandPrince, MeetsTolerance) {
  // Global error over ~3 periods stays within a small multiple of the local
  // tolerance (error per unit step accumulates roughly linearly).
  for (double tol : {1e-6, 1e-8, 1e-10}) EXPECT_LT(global_error(tol), 50 * tol) << tol;
}

TEST(DormandPrince, StepCountScalesAsFifthOrder) {
  // For an order-5 local error, steps ~ tol^(-1/5): 1e-5 less tolerance means
  // about 10x more steps.  A lower-order bug would show 18x (order 4) or more.
  long n1 = 0, n2 = 0;
  global_error(1e-6, &n1);
  global_error(1e-11, &n2);
  const double ratio = static_cast<double>(n2) / n1;
  EXPECT_GT(ratio, 7.0);
  EXPECT_LT(ratio, 14.0);
}

TEST(DormandPrince, DenseOutputIsAccurateInsideSteps) {
  DormandPrince5<2, Oscillator> dp(Oscillator{}, StepControl{1e-9, 1e-9, 1e-14, 1e30}, {1.0, 1.0});
  dp.reset(0.0, {1.0, 0.0}, 0.01);
  DenseStep<2> s;
  double worst = 0.0;
  while (dp.t() < 10.0) {
    ASSERT_TRUE(dp.step(s));
    for (double f : {0.1, 0.37, 0.5, 0.81}) {
      const double t = s.t0 + f * s.h;
      worst = std::max(worst, std::abs(s.component(0, t) - std::cos(t)));
      worst = std::max(worst, std::abs(s.component(1, t) + std::sin(t)));
    }
    // The extension interpolates the step's end points exactly.
    EXPECT_NEAR(s.component(0, s.t0 + s.h), dp.y()[0], 1e-15);
  }
  EXPECT_LT(worst, 1e-7);
}

TEST(DormandPrince, GivesUpWhenTheStepUnderflows) {
  // y' = 1/(1 - t) blows up at t = 1: the controller shrinks h until h_min.
  auto rhs = [](double t, const std::array<double, 1>&, std::array<double, 1>& d) { d[0] = 1.0 / (1.0 - t); };
  DormandPrince5<1, decltype(rhs)> dp(rhs, StepControl{1e-10, 1e-10, 1e-9, 1e30}, {1.0});
  dp.reset(0.0, {0.0}, 0.1);
  DenseStep<1> s;
  int n = 0;
  while (dp.step(s) && n < 100000) ++n;
  EXPECT_LT(n, 100000);
  EXPECT_LT(dp.t(), 1.0);
}

}  // namespace
}  // namespace lc

namespace lc {
namespace {

TEST(DormandPrince, ControllerLog2AndExp2AreAccurateEnough) {
  // The step-size controller's own log2/exp2: 1e-5 relative over the range
  // the controller sees (errors 1e-10 .. 1e10, exponents -5 .. 5).
  for (double x = 1e-10; x < 1e10; x *= 1.37)
    EXPECT_NEAR(detail::controller_log2(x), std::log2(x), 1e-5) << x;
  for (double y = -40; y < 40; y += 0.173)
    EXPECT_NEAR(detail::controller_exp2(y) / std::exp2(y), 1.0, 1e-5) << y;
}

}  // namespace
}  // namespace lc
