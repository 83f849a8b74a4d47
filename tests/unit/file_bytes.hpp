// A file's bytes as a string, and a file made of given bytes: for tests
// that damage a written file (cut it short, change a byte) and try it again.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace lc::test {

inline std::string bytes_of(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void put(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream(p, std::ios::binary | std::ios::trunc) << bytes;
}

}  // namespace lc::test
