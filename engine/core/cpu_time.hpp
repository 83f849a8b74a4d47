#pragma once
// What a measurement of speed needs from the OS: the calling thread's CPU
// time (what work cost however busy the machine was: wall time also counts
// the waits for a core) and the machine's load beside it.

#include <optional>
#include <string>

namespace lc {

// CPU time of the calling thread so far, in seconds (CLOCK_THREAD_CPUTIME_ID).
double thread_cpu_seconds();

// CPU time of the whole process so far, every thread's (libraries' own
// threads too), user and system, in seconds (getrusage RUSAGE_SELF).
double process_cpu_seconds();

// The load averages over 1, 5 and 15 minutes (/proc/loadavg), or nullopt
// where the file is missing or does not read.
struct LoadAverage {
  double one = 0.0, five = 0.0, fifteen = 0.0;
};
std::optional<LoadAverage> load_average();

// "load 1.52 / 1.10 / 0.80 (1, 5, 15 min) on 2 cores", or "load unknown
// (no /proc/loadavg) on 2 cores": for a benchmark's report.
std::string describe_load(int cores);

}  // namespace lc
