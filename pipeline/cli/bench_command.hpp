#pragma once
// `lightcone bench`: speed (rays per core-second, one thread and all) and
// accuracy (against a tight-tolerance render) on the benchmark shots of
// shots/bench/.  Numbers go into issue notes and docs/performance.md.

#include <filesystem>
#include <string>
#include <vector>

namespace lc {

struct BenchCommand {
  std::vector<std::filesystem::path> shots;  // default: shots/bench/kerr_disk.lua, dihole_sphere.lua
  int threads = 0;                           // 0: every core
  int repeats = 3;                           // best of N (the machines are shared and noisy)
  double seconds = 0.0;                      // each timed run traces the image again until this long has passed
  double reference_tolerance = 1e-13;
  double tolerance = 0.0;  // 0: the production default (constants.hpp)
  std::string kerr_chart = "bl-mino";  // how Kerr rays are integrated in the timed run: bl-mino or kerr-schild
};

int run_bench(const BenchCommand& cmd);

}  // namespace lc
