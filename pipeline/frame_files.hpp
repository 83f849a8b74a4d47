#pragma once
// Where a shot's frames live and how one is written: DIR/<shot>.<NNNN>.exr
// (linear float, zip, data layers) and DIR/<shot>.<NNNN>.png (8-bit sRGB),
// each written to a temporary name, synced and renamed, so a frame's final
// name never shows a half-written file.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "image/image.hpp"

namespace lc {

std::filesystem::path frame_path(const std::filesystem::path& dir, const std::string& shot, int frame,
                                 const char* extension);

// Writes both files of one frame; throws std::runtime_error naming the file
// (and removes its temporaries) on failure.
void write_frame_files(const std::filesystem::path& dir, const std::string& shot, int frame, const FrameImage& image,
                       const std::vector<std::pair<std::string, std::string>>& metadata);

}  // namespace lc
