// A shot script written into a test's scratch directory.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "scratch_dir.hpp"

namespace lc::test {

// Writes `text` as the file `name` in `dir`; returns its path.
inline std::filesystem::path write_shot(const ScratchDir& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path file = dir / name;
  std::ofstream(file) << text;
  return file;
}

}  // namespace lc::test
