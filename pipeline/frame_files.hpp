#pragma once
// Where a shot's frames live: DIR/<shot>.<NNNN>.exr (linear float, zip, data
// layers) and DIR/<shot>.<NNNN>.png (8-bit sRGB).  Writing them is the frame
// store's job (farm/frame_store.hpp): temporary name, read back, sync, rename.

#include <filesystem>
#include <string>

namespace lc {

std::filesystem::path frame_path(const std::filesystem::path& dir, const std::string& shot, int frame,
                                 const char* extension);

}  // namespace lc
