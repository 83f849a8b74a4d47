#pragma once
// Internal to engine/image: the one reader behind read_image_linear and
// Texture::load, parameterised by the phrase its error messages
// start with.

#include <filesystem>

#include "image/frame_image.hpp"

namespace lc::detail {

// Reads `path` into linear RGB as documented at read_image_linear; error
// messages read "<what> '<path>': <reason>" (what: "cannot read image",
// "cannot load texture").  Images of more than max_pixels pixels are refused
// from their header, before anything is allocated.
FrameImage read_linear_rgb(const std::filesystem::path& path, const char* what,
                           long max_pixels = long{max_image_side} * max_image_side);

}  // namespace lc::detail
