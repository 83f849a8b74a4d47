#include "frame_files.hpp"

#include <fmt/format.h>

namespace lc {

std::filesystem::path frame_path(const std::filesystem::path& dir, const std::string& shot, int frame,
                                 const char* extension) {
  return dir / fmt::format("{}.{:04d}.{}", shot, frame, extension);
}

}  // namespace lc
