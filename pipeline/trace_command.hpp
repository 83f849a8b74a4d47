#pragma once
// `lightcone trace SHOT.lua --frame F --pixel I,J [-o path.csv]`: follows the
// ray through the centre of one pixel and writes its path (CSV as
// `lightcone geodesic` writes, traced into the past) and what it hit.

#include <filesystem>
#include <optional>
#include <string>

namespace lc {

struct TraceCommand {
  std::filesystem::path shot;
  int frame = 0;
  std::string pixel;  // "I,J"
  std::optional<std::filesystem::path> output;
  std::optional<std::string> size;
  double scale = 1.0;
};

int run_trace(const TraceCommand& cmd);

}  // namespace lc
