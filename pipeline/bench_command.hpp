#pragma once
// `lightcone bench`: rays per second on fixed scenes, one thread and all
// threads.  Numbers go into issue notes and docs/performance.md.

namespace lc {

struct BenchCommand {
  int size = 128;      // rays per side of the fixed camera grid
  int threads = 0;     // 0: every core
  int repeats = 3;     // best of N (the machines are shared and noisy)
};

int run_bench(const BenchCommand& cmd);

}  // namespace lc
