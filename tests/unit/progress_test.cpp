// Progress on standard error (telemetry/progress.hpp): the numbers a user
// reads at a glance, and a step that stops when its check says so.

#include <cstdio>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "telemetry/progress.hpp"

namespace lc::farm {
namespace {

// What was written to f.
std::string text_of(std::FILE* f) {
  std::rewind(f);
  std::string out;
  for (int c; (c = std::fgetc(f)) != EOF;) out += static_cast<char>(c);
  return out;
}

TEST(Progress, DurationsAndCountsAreCoarse) {
  EXPECT_EQ(format_duration(9.4), "9s");
  EXPECT_EQ(format_duration(252), "4m12s");
  EXPECT_EQ(format_duration(11100), "3h05m");
  EXPECT_EQ(format_duration(-1), "?");
  EXPECT_EQ(format_count(950), "950");
  EXPECT_EQ(format_count(45200), "45.2k");
  EXPECT_EQ(format_count(4.56e6), "4.56M");
}

TEST(Progress, ALineSaysFramesShareRateAndEta) {
  RunProgress p;
  p.frames_total = 50;
  p.frames_stored = 12;
  p.rows_total = 1000;
  p.rows_done = 250;
  p.stats.rays = 90000;
  // A quarter done in 60 s: three quarters more take 180 s.
  EXPECT_EQ(progress_line(p, 60.0), "12/50 frames, 25%, 1.5k rays/s, ETA 3m00s");
}

// Each step calls the check before anything else, and what it throws ends
// the step (the render's check throws Interrupted after a signal).
TEST(Progress, AStepCallsItsCheckAndStopsWhenItThrows) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  int checks = 0;
  StepProgress step("evaluating the frames", 10, 0.0, [&checks] {
    if (++checks == 3) throw std::runtime_error("stop");
  }, 0.0, out);
  step(1);
  step(2);
  EXPECT_THROW(step(3), std::runtime_error);
  EXPECT_EQ(checks, 3);
  EXPECT_EQ(text_of(out), "");  // interval 0: no lines
  std::fclose(out);
}

TEST(Progress, AStepSaysItsShareOnceDue) {
  std::FILE* out = std::tmpfile();
  ASSERT_NE(out, nullptr);
  StepProgress step("auto exposure: metering", 4, 1e-9, nullptr, 0.0, out);
  step(1);
  EXPECT_EQ(text_of(out).rfind("render: auto exposure: metering: 1/4 frames, 25%, ", 0), 0u) << text_of(out);
  std::fclose(out);
}

}  // namespace
}  // namespace lc::farm
