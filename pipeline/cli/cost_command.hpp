#pragma once
// `lightcone cost DIR...`: what the frames of each render directory cost,
// read back from its journal (core-seconds per frame, samples traced and
// reused, when they were stored), with a per-frame CSV on request.

#include <filesystem>
#include <optional>
#include <vector>

namespace lc {

struct CostCommand {
  std::vector<std::filesystem::path> dirs;
  std::optional<std::filesystem::path> csv;  // one row per frame
};

int run_cost(const CostCommand& cmd);

}  // namespace lc
