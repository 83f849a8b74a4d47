#pragma once
// How many render threads a process runs by default.

namespace lc::farm {

// CPUs this process may run on (its affinity mask: honours taskset and an
// MPI launcher's binding), at least 1.
int usable_cpus();

// Threads for one of `sharers` worker processes on this node: all usable
// CPUs if the launcher bound us to a subset, else an equal share.
int default_threads(int sharers);

}  // namespace lc::farm
