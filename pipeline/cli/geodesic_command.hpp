#pragma once
// `lightcone geodesic SPEC.lua [-o out.csv]`: trace one geodesic and write its
// samples as CSV (docs/geodesic.md).

#include <filesystem>
#include <optional>

namespace lc {

struct GeodesicCommand {
  std::filesystem::path spec;
  std::optional<std::filesystem::path> output;  // stdout when absent
};

// Returns the process exit code; errors are thrown (std::exception) with a
// message naming the file and field.
int run_geodesic(const GeodesicCommand& cmd);

}  // namespace lc
