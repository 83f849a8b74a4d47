#include "transport/threads.hpp"

#include <algorithm>
#include <thread>

#include <sched.h>
#include <unistd.h>

namespace lc::farm {

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "";
  return name;
}

int usable_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0) return std::max(1, CPU_COUNT(&set));
  return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// Bound to fewer CPUs than the machine has: the launcher (or taskset) chose
// our share.  Unbound: divide the machine among the workers on it.
int default_threads(int sharers) {
  const int usable = usable_cpus();
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (usable < all) return usable;
  return std::max(1, all / std::max(1, sharers));
}

}  // namespace lc::farm
