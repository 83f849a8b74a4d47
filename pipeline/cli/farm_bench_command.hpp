#pragma once
// `lightcone farm-bench`: how fast the farm itself is, with working sets
// that cost nothing to render.  Under `mpirun -n N` it times the master
// handing out sets and assembling the returned stripes (real message sizes
// for the image size, no tracing); without MPI the local queue.  It also
// times writing one frame (EXR + PNG), the master's other per-frame cost.
// docs/cluster.md turns the numbers into how many workers one master feeds.

#include <optional>
#include <string>

namespace lc {

struct FarmBenchCommand {
  std::string size = "1280x720";
  int stripes = 512;
  int frames = 16;
  bool layers = false;
  int threads = 0;  // worker threads (0: as render)
};

int run_farm_bench(const FarmBenchCommand& cmd);

}  // namespace lc
