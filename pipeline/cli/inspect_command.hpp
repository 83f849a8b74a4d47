#pragma once
// `lightcone inspect SHOT.lua [--frames A:B]`: the evaluated scene of each
// frame as JSON on standard output, without rendering.

#include <filesystem>
#include <optional>
#include <string>

namespace lc {

struct InspectCommand {
  std::filesystem::path shot;
  std::optional<std::string> frames;
};

int run_inspect(const InspectCommand& cmd);

}  // namespace lc
