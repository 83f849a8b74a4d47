// The lightcone command line: parses flags (the only file that includes
// CLI11) and hands each subcommand a plain options struct.

#include <cstdio>
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "bench_command.hpp"
#include "geodesic_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"lightcone: general-relativistic black-hole animation, traced along null geodesics", "lightcone"};
  app.set_version_flag("--version", std::string("lightcone ") + LIGHTCONE_VERSION);
  app.require_subcommand(1);

  lc::GeodesicCommand geo;
  auto* geodesic = app.add_subcommand(
      "geodesic", "Trace one null or timelike geodesic described by a Lua spec and write its samples as CSV");
  geodesic->add_option("spec", geo.spec, "Geodesic spec script (docs/geodesic.md)")->required()->check(CLI::ExistingFile);
  geodesic->add_option("-o,--output", geo.output, "CSV file to write (default: standard output)");

  lc::BenchCommand bench;
  auto* bench_cmd = app.add_subcommand("bench", "Measure rays per second on fixed scenes, one thread and all threads");
  bench_cmd->add_option("--size", bench.size, "Rays per side of the camera grid")->check(CLI::Range(1, 4096));
  bench_cmd->add_option("--threads", bench.threads, "Threads for the parallel run (default: every core)")
      ->check(CLI::Range(1, 1024));
  bench_cmd->add_option("--repeats", bench.repeats, "Best of this many runs")->check(CLI::Range(1, 100));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }

  try {
    if (*geodesic) return lc::run_geodesic(geo);
    if (*bench_cmd) return lc::run_bench(bench);
  } catch (const std::exception& e) {
    fmt::print(stderr, "lightcone: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
