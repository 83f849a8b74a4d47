#pragma once
// One benchmark shot measured: rays per core-second (the threads' CPU time,
// so a loaded machine does not halve it) with one thread and with all, rays
// per second of wall time beside it, and accuracy against lightcone's own tight-tolerance render of
// the same frame (docs/performance.md).

#include <filesystem>
#include <string>

#include "geodesic/null_ray.hpp"
#include "render/accuracy.hpp"

namespace lc {

struct ShotBenchResult {
  std::string name;
  int width = 0, height = 0;
  long rays = 0, steps = 0;
  double seconds_one = 0.0, seconds_all = 0.0;  // wall time of one image, best of the repeats
  double cpu_one = 0.0, cpu_all = 0.0;          // the threads' CPU time for one image, summed, best of the repeats
  int threads = 1;
  double tolerance = 0.0, reference_tolerance = 0.0;
  AccuracyReport accuracy;
};

// Renders frame 0 of `shot` (one ray through each pixel centre, at the shot's
// size) `repeats` times with one thread and with `threads`, then once at
// `reference_tolerance`, and compares.
// `tolerance` 0 means the production default; `chart` is how the timed run
// integrates Kerr rays (the reference always takes the Boyer–Lindquist–Mino
// path, which converges faster: docs/performance.md).
// How the speed is timed: the best of `repeats` runs, each tracing the
// image as many times as it takes to fill `seconds` (at least once): a
// small bench image is over in ~0.1 s, too short to time two threads on a
// shared machine.
struct BenchTiming {
  int repeats = 3;
  double seconds = 0.0;
};

ShotBenchResult bench_shot(const std::filesystem::path& shot, int threads, BenchTiming timing, double tolerance,
                           double reference_tolerance, KerrChart chart = KerrChart::boyer_lindquist_mino);

}  // namespace lc
