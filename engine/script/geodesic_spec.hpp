#pragma once
// A geodesic spec script (for `lightcone geodesic`) -> GeodesicProblem.
// Format reference: docs/geodesic.md.

#include <filesystem>
#include <string>
#include <vector>

#include "geodesic/geodesic_solver.hpp"

namespace lc {

struct GeodesicSpec {
  GeodesicProblem problem;
  bool polar_scene = false;  // output in Boyer–Lindquist (t, r, theta, phi), else Cartesian
};

// A spec script returns one spec table or an array of them (a bundle).
struct GeodesicSpecs {
  std::vector<GeodesicSpec> specs;
  bool bundle = false;
};

// Runs the script sandboxed and reads what it returns.  Throws
// lua::ScriptError (script failed: file:line and traceback) or
// lua::FieldError (bad value: file, field and problem).
GeodesicSpecs load_geodesic_specs(const std::filesystem::path& file);

}  // namespace lc
