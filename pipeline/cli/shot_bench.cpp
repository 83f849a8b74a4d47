#include "shot_bench.hpp"

#include <span>

#include <chrono>
#include <functional>
#include <vector>

#include "core/cpu_time.hpp"
#include "core/parallel_for.hpp"
#include "render/scene_builder.hpp"
#include "render/scene_visit.hpp"
#include "render/trace.hpp"
#include "script/shot.hpp"

namespace lc {

namespace {

// Pixel-centre samples of the whole image, rows handed out to `threads`.
// Adds the threads' CPU time, summed, to *cpu_seconds when given.
std::vector<RaySample> trace_all(const Scene& scene, int width, int height, int threads, long* steps,
                                 double* cpu_seconds = nullptr) {
  std::vector<RaySample> out(static_cast<std::size_t>(width) * height);
  const std::size_t rows = static_cast<std::size_t>(height);
  // Per worker: the row's directions (made once) and the steps counted.
  std::vector<std::vector<Vec3>> dirs(parallel_workers(rows, threads),
                                      std::vector<Vec3>(static_cast<std::size_t>(width)));
  std::vector<long> counted(dirs.size(), 0);
  double cpu = 0.0;
  const double cpu0 = thread_cpu_seconds();
  parallel_for(rows, {.threads = threads, .helpers_cpu = &cpu}, [&](std::size_t j, std::size_t worker) {
    visit_scene(
        [&](const auto& sc) {
          // A row at a time, as the renderer traces (several rays at once
          // where the spacetime allows).
          std::vector<Vec3>& row_dirs = dirs[worker];
          for (int i = 0; i < width; ++i) row_dirs[i] = sc.camera.direction(i + 0.5, j + 0.5);
          const std::span<RaySample> row(out.data() + j * width, static_cast<std::size_t>(width));
          trace_batch(sc, std::span<const Vec3>(row_dirs), row);
          long local = 0;
          for (const RaySample& s : row) local += s.hit.steps;
          counted[worker] += local;
        },
        scene);
  });
  cpu += thread_cpu_seconds() - cpu0;
  long total = 0;
  for (long c : counted) total += c;
  if (steps) *steps = total;
  if (cpu_seconds) *cpu_seconds += cpu;
  return out;
}

// Wall and CPU seconds per call of f(double* cpu), over as many calls as
// fill `at_least` seconds of wall time; f adds its threads' CPU time.
struct CallTime {
  double wall = 0.0, cpu = 0.0;
};
CallTime time_of(const std::function<void(double*)>& f, double at_least) {
  const auto t0 = std::chrono::steady_clock::now();
  double cpu = 0.0;
  for (int calls = 1;; ++calls) {
    f(&cpu);
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (s >= at_least) return {s / calls, cpu / calls};
  }
}

}  // namespace

ShotBenchResult bench_shot(const std::filesystem::path& file, int threads, BenchTiming timing, double tolerance,
                           double reference_tolerance, KerrChart chart) {
  Shot shot(file);
  const ShotInfo& info = shot.info();
  const SceneSpec fs = shot.frame(0);
  ShotResources resources(shot.asset_dirs());
  ShotBenchResult r;
  r.name = info.name;
  r.width = info.width;
  r.height = info.height;
  r.rays = static_cast<long>(info.width) * info.height;
  r.threads = threads;
  RayOptions defaults;
  if (tolerance > 0.0) defaults.control.rtol = defaults.control.atol = tolerance;
  defaults.kerr_chart = chart;
  r.tolerance = defaults.control.rtol;
  r.reference_tolerance = reference_tolerance;
  const Scene scene = build_scene(fs, file, 0, info.width, info.height, resources, defaults);
  std::vector<RaySample> test;
  r.seconds_one = r.seconds_all = r.cpu_one = r.cpu_all = 1e300;
  // The best of the repeats, each figure on its own: the least CPU time is
  // the run least disturbed (cache, frequency), the least wall time the one
  // that waited least for a core.
  for (int k = 0; k < timing.repeats; ++k) {
    const CallTime one =
        time_of([&](double* cpu) { test = trace_all(scene, r.width, r.height, 1, &r.steps, cpu); }, timing.seconds);
    r.seconds_one = std::min(r.seconds_one, one.wall);
    r.cpu_one = std::min(r.cpu_one, one.cpu);
    if (threads > 1) {
      const CallTime all =
          time_of([&](double* cpu) { trace_all(scene, r.width, r.height, threads, nullptr, cpu); }, timing.seconds);
      r.seconds_all = std::min(r.seconds_all, all.wall);
      r.cpu_all = std::min(r.cpu_all, all.cpu);
    }
  }
  RayOptions tight;
  tight.control.rtol = tight.control.atol = reference_tolerance;
  tight.control.h_min = 1e-14;
  tight.escape = EscapeRule::fixed;  // integrated out to 1000 M, whatever the scene allows
  const Scene reference_scene = build_scene(fs, file, 0, info.width, info.height, resources, tight);
  const std::vector<RaySample> reference = trace_all(reference_scene, r.width, r.height, threads, nullptr);
  r.accuracy = compare_samples(reference, test, fs);
  return r;
}

}  // namespace lc
