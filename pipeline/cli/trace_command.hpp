#pragma once
// `lightcone trace SHOT.lua --frame F --pixel I,J [-o path.csv] [--json]`:
// follows the ray through the centre of one pixel and writes its path (CSV
// as `lightcone geodesic` writes, traced into the past) and what it hit (a
// line on standard error, or with --json one JSON object on standard
// output).

#include <filesystem>
#include <optional>
#include <string>

#include "job/delivery_flags.hpp"

namespace lc {

struct TraceCommand {
  std::filesystem::path shot;
  int frame = 0;
  std::string pixel;  // "I,J"
  std::optional<std::filesystem::path> output;
  std::optional<std::string> size;
  double scale = 1.0;
  bool json = false;  // the report as one JSON object on standard output (the path only with -o)
  DeliveryFlags delivery;  // as render --camera ... --sky: the pixel of the frame delivered so
};

int run_trace(const TraceCommand& cmd);

}  // namespace lc
