#pragma once
// `lightcone starfield -o FILE [--width W] [--seed S]`: writes the procedural
// star field as an equirectangular sRGB PNG (how shots/textures/starfield.png
// was made).

#include <cstdint>
#include <filesystem>

namespace lc {

struct StarfieldCommand {
  std::filesystem::path output;
  int width = 2048;  // height is width / 2
  std::uint32_t seed = 1;
};

int run_starfield(const StarfieldCommand& cmd);

}  // namespace lc
