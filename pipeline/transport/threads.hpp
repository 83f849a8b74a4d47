#pragma once
// How many render threads a process runs by default, and where it runs.

#include <string>

namespace lc::farm {

// This node's name (gethostname), "" if it has none: for the event log.
std::string host_name();

// CPUs this process may run on (its affinity mask: honours taskset and an
// MPI launcher's binding), at least 1.
int usable_cpus();

// Threads for one of `sharers` worker processes on this node: all usable
// CPUs if the launcher bound us to a subset, else an equal share.
int default_threads(int sharers);

}  // namespace lc::farm
