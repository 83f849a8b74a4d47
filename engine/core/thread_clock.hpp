#pragma once
// CPU time of the calling thread: what work cost however busy the machine
// was (wall time would count the waits for a core).  The farm's working
// sets and the point-star stage are measured with it.

#include <ctime>

namespace lc {

// Seconds of CPU the calling thread has used since it started.
inline double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace lc
