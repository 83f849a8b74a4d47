#include "bench_command.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "core/cpu_time.hpp"
#include "script/script_paths.hpp"
#include "geodesic/null_ray.hpp"
#include "shot_bench.hpp"

namespace lc {

int run_bench(const BenchCommand& cmd) {
  KerrChart chart = KerrChart::boyer_lindquist_mino;
  if (cmd.kerr_chart == "kerr-schild") chart = KerrChart::kerr_schild;
  else if (cmd.kerr_chart != "bl-mino")
    throw std::invalid_argument(fmt::format("--kerr-chart '{}': choose bl-mino or kerr-schild", cmd.kerr_chart));
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int all = cmd.threads > 0 ? cmd.threads : cores;
  std::vector<std::filesystem::path> shots = cmd.shots;
  if (shots.empty()) {
    const auto dir = library_dir().parent_path() / "shots" / "bench";
    shots = {dir / "kerr_disk.lua", dir / "dihole_sphere.lua"};
  }
  if (!(cmd.seconds >= 0.0) || cmd.seconds > 3600.0)
    throw std::invalid_argument(fmt::format("--seconds {}: must be between 0 and 3600", cmd.seconds));
  fmt::print("lightcone bench: one ray per pixel centre, best of {}{}; accuracy against tolerance {:g}\n",
             cmd.repeats, cmd.seconds > 0.0 ? fmt::format(" runs of at least {:g} s", cmd.seconds) : "",
             cmd.reference_tolerance);
  // Core-seconds are the threads' CPU time: on a loaded machine they stay
  // what the rays cost, while wall time grows with the waits for a core.
  fmt::print("rays per core-second from the threads' CPU time; rays/s from wall time; {}\n",
             describe_load(cores));
  for (const auto& file : shots) {
    const ShotBenchResult r =
        bench_shot(file, all, {cmd.repeats, cmd.seconds}, cmd.tolerance, cmd.reference_tolerance, chart);
    const AccuracyReport& a = r.accuracy;
    fmt::print("\n{} ({}x{}, tolerance {:g}{})\n", r.name, r.width, r.height, r.tolerance,
               chart == KerrChart::kerr_schild ? ", Kerr rays in Kerr-Schild" : "");
    fmt::print("  speed:    {:.0f} rays per core-second on 1 thread, {:.1f} steps per ray, {:.0f} steps per "
               "core-second; {:.0f} rays/s of wall time\n",
               r.rays / r.cpu_one, double(r.steps) / r.rays, r.steps / r.cpu_one, r.rays / r.seconds_one);
    if (all > 1)
      fmt::print("            {:.0f} rays per core-second on {} threads ({:.2f} of one thread's); {:.0f} rays/s of "
                 "wall time ({:.2f}x one thread's)\n",
                 r.rays / r.cpu_all, all, r.cpu_one / r.cpu_all, r.rays / r.seconds_all, r.seconds_one / r.seconds_all);
    fmt::print("  {}\n", describe_load(cores));  // after the shot, as it ran
    fmt::print("  accuracy: {} of {} pixels differ in hit kind, {} in checker cell or colour\n", a.kind_mismatches,
               a.pixels, a.cell_mismatches);
    if (a.disk_pixels > 0)
      fmt::print("            disk hits ({}): |dr| median {:.2e}, p99 {:.2e}, max {:.2e} M; |dphi| median {:.2e}, "
                 "p99 {:.2e}, max {:.2e} rad\n",
                 a.disk_pixels, a.dr_median, a.dr_p99, a.dr_max, a.dphi_median, a.dphi_p99, a.dphi_max);
  }
  return 0;
}

}  // namespace lc
