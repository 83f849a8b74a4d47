#pragma once
// `lightcone render SHOT.lua --out DIR [...]`: renders frames of a shot with
// every core and writes them (docs/cli.md).

#include <filesystem>
#include <optional>
#include <string>

namespace lc {

struct RenderCommand {
  std::filesystem::path shot;
  std::filesystem::path out;
  std::optional<std::string> frames;  // "A", "A:B" or "A:B:STEP"
  std::optional<std::string> size;    // "WxH"
  double scale = 1.0;
  std::optional<int> supersample;
  bool layers = false;
  int threads = 0;
};

int run_render(const RenderCommand& cmd);

// Image size after --size and --scale, for render and trace alike.  Throws
// std::invalid_argument naming the flag.
std::pair<int, int> output_size(int width, int height, const std::optional<std::string>& size, double scale);

}  // namespace lc
