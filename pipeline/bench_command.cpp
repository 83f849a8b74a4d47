#include "bench_command.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "script/script_paths.hpp"
#include "geodesic/null_ray.hpp"
#include "shot_bench.hpp"

namespace lc {

int run_bench(const BenchCommand& cmd) {
  KerrChart chart = KerrChart::boyer_lindquist_mino;
  if (cmd.kerr_chart == "kerr-schild") chart = KerrChart::kerr_schild;
  else if (cmd.kerr_chart != "bl-mino")
    throw std::invalid_argument(fmt::format("--kerr-chart '{}': choose bl-mino or kerr-schild", cmd.kerr_chart));
  const int all = cmd.threads > 0 ? cmd.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
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
  for (const auto& file : shots) {
    const ShotBenchResult r =
        bench_shot(file, all, {cmd.repeats, cmd.seconds}, cmd.tolerance, cmd.reference_tolerance, chart);
    const AccuracyReport& a = r.accuracy;
    fmt::print("\n{} ({}x{}, tolerance {:g}{})\n", r.name, r.width, r.height, r.tolerance,
               chart == KerrChart::kerr_schild ? ", Kerr rays in Kerr-Schild" : "");
    fmt::print("  speed:    {:.0f} rays per core-second on 1 thread, {:.1f} steps per ray, {:.0f} steps/s\n",
               r.rays / r.seconds_one, double(r.steps) / r.rays, r.steps / r.seconds_one);
    if (all > 1)
      fmt::print("            {:.0f} rays/s on {} threads ({:.0f} per core-second, {:.2f} of linear)\n",
                 r.rays / r.seconds_all, all, r.rays / r.seconds_all / all, r.seconds_one / r.seconds_all / all);
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
