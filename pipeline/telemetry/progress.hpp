#pragma once
// Progress of a render on standard error: on a terminal one live line
// redrawn in place (frames done/total, rays per second, ETA); otherwise a
// plain line every few seconds, for logs.  The master alone reports.

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>

#include "telemetry/run_progress.hpp"

namespace lc::farm {

enum class ProgressStyle { live, plain, quiet };

// "3h05m", "4m12s", "9s": coarse enough to read at a glance.
std::string format_duration(double seconds);
// "12.3k", "4.56M": rays per second on the live line.
std::string format_count(double value);
// One progress line (no prefix), e.g. "12/50 frames, 31%, 45.2k rays/s, ETA 3m12s".
std::string progress_line(const RunProgress& p, double seconds);

class Progress {
 public:
  // `interval` is the time between plain lines (live lines redraw every
  // quarter second).  The clock starts here.
  Progress(ProgressStyle style, double interval, std::FILE* out = stderr);
  // Draws a line if one is due.
  void tick(const RunProgress& p);
  // Ends the live line (so the next message starts on a fresh one).
  void finish();
  double elapsed() const;

 private:
  ProgressStyle style_;
  double interval_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_;
  bool drawn_ = false;
};

// The progress of a step before the frames render (evaluating the shot's
// frames, metering its exposure), which takes minutes on a long shot: a
// plain line "render: <what>: <done>/<total> frames, <p>%, <s> s" on
// stderr, the first once `first` seconds have passed and then every
// `interval` seconds (0: none); and `check` called at each step, which may
// throw to stop the step (the render's throws Interrupted after a signal,
// cli/interrupt.hpp).  Not thread-safe.
class StepProgress {
 public:
  StepProgress(std::string what, std::size_t total, double interval, std::function<void()> check, double first = 2.0,
               std::FILE* out = stderr);
  // `done` of the total are done: says so if due; then checks.
  void operator()(std::size_t done);
  // The same where the total has grown to `total`.
  void operator()(std::size_t done, std::size_t total) {
    total_ = total;
    (*this)(done);
  }

 private:
  // Prints the line for `done` frames.
  void say(std::size_t done);
  std::string what_;
  std::size_t total_;
  double interval_, first_;
  std::function<void()> check_;
  std::FILE* out_;
  std::chrono::steady_clock::time_point start_, last_;
  bool said_ = false;
};

// Live on a terminal, else plain (quiet when the interval is 0).
ProgressStyle progress_style_for(std::FILE* out, double interval);

}  // namespace lc::farm
