#pragma once
// Internal to engine/image: the one reader behind read_image_linear and
// Texture::load, parameterised by the phrase its error messages
// start with.

#include <filesystem>

#include "image/frame_image.hpp"

namespace lc::detail {

// Reads `path` into linear RGB as documented at read_image_linear; error
// messages read "<what> '<path>': <reason>" (what: "cannot read image",
// "cannot load texture").
FrameImage read_linear_rgb(const std::filesystem::path& path, const char* what);

}  // namespace lc::detail
