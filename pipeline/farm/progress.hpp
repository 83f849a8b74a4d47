#pragma once
// Progress of a render on standard error: on a terminal one live line
// redrawn in place (frames done/total, rays per second, ETA); otherwise a
// plain line every few seconds, for logs.  The master alone reports.

#include <chrono>
#include <cstdio>
#include <string>

#include "farm/work_queue.hpp"

namespace lc::farm {

enum class ProgressStyle { live, plain, quiet };

// "3h05m", "4m12s", "9s": coarse enough to read at a glance.
std::string format_duration(double seconds);
// "12.3k", "4.56M": rays per second on the live line.
std::string format_count(double value);
// One progress line (no prefix), e.g. "12/50 frames, 31%, 45.2k rays/s, ETA 3m12s".
std::string progress_line(const QueueProgress& p, double seconds);

class Progress {
 public:
  // `interval` is the time between plain lines (live lines redraw every
  // quarter second).  The clock starts here.
  Progress(ProgressStyle style, double interval, std::FILE* out = stderr);
  // Draws a line if one is due.
  void tick(const QueueProgress& p);
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

// Live on a terminal, else plain (quiet when the interval is 0).
ProgressStyle progress_style_for(std::FILE* out, double interval);

}  // namespace lc::farm
