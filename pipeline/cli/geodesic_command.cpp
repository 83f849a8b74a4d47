#include "geodesic_command.hpp"

#include <cstdio>
#include <stdexcept>

#include <fmt/format.h>

#include "command_output.hpp"
#include "geodesic_csv.hpp"
#include "script/geodesic_spec.hpp"

namespace lc {

namespace {

const char* parameter_name(StopParameter p) {
  switch (p) {
    case StopParameter::affine: return "affine parameter";
    case StopParameter::proper_time: return "proper time";
    case StopParameter::coordinate_time: return "coordinate time";
  }
  return "?";
}

}  // namespace

int run_geodesic(const GeodesicCommand& cmd) {
  const GeodesicSpecs specs = load_geodesic_specs(cmd.spec);
  const bool tetrad = specs.specs.front().problem.tetrad.has_value();
  for (const auto& s : specs.specs)
    if (s.problem.tetrad.has_value() != tetrad)
      throw std::invalid_argument(fmt::format(
          "{}: all rays of a bundle must agree on 'transport' (the CSV has one set of columns)", cmd.spec.string()));

  // The CSV records one chart (its first line): every ray's x0..x3 in it.
  std::vector<Spacetime> spacetimes;
  for (const auto& s : specs.specs) {
    spacetimes.push_back(s.problem.spacetime);
    const Spacetime& first = spacetimes.front();
    if (scene_chart(s.problem.spacetime) != scene_chart(first))
      throw std::invalid_argument(fmt::format(
          "{}: all rays of a bundle must be in one scene chart (the CSV records one): ray 1 is in {} ({}), ray {} in "
          "{} ({})",
          cmd.spec.string(), spacetime_name(first), csv_chart_name(scene_chart(first)), spacetimes.size(),
          spacetime_name(s.problem.spacetime), csv_chart_name(scene_chart(s.problem.spacetime))));
  }
  std::string csv = geodesic_csv_header(spacetimes, tetrad, specs.bundle);
  int index = 0;
  for (const auto& spec : specs.specs) {
    ++index;
    const GeodesicPath path = solve_geodesic(spec.problem);
    append_geodesic_csv(csv, spec.problem.spacetime, path, tetrad, specs.bundle ? std::optional(index) : std::nullopt);
    const auto& pb = spec.problem;
    fmt::print(stderr, "lightcone geodesic: {}{} samples, stop reason: {}{}, {} steps, max |g(u,u) drift| {:.2e}\n",
               specs.bundle ? fmt::format("ray {}: ", index) : "", path.samples.size(), to_string(path.reason),
               path.reason == StopReason::reached ? fmt::format(" ({} {})", parameter_name(pb.stop_parameter), pb.stop_value)
               : path.reason == StopReason::escaped ? fmt::format(" (to {})", path.end)
                                                    : "",
               path.steps, path.max_constraint_drift);
  }
  // Everything is computed before anything is written: a failure leaves no
  // partial file.
  write_output(cmd.output, csv);
  return 0;
}

}  // namespace lc
