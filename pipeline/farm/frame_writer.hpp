#pragma once
// Writes a frame's files so that a final name only ever shows a complete,
// readable file: each file goes to a temporary name, is read back (the
// image writers do not always notice a failed write: on a full disk a PNG
// can come out empty without an error), synced, and only then renamed.
// Temporaries are named "<final>.tmp-<pid>", as frame_files.hpp does, so
// the frame store's cleanup finds those of a killed render.

#include <filesystem>
#include <string>

#include "image/image.hpp"

namespace lc::farm {

enum class FrameFormat { exr, png };

// Writes `image` to `final` in `format`, verified and atomically.  Throws
// std::runtime_error naming the file; leaves no temporary behind.
void write_verified(const std::filesystem::path& final, FrameFormat format, const FrameImage& image,
                    const ImageMetadata& metadata = {});

}  // namespace lc::farm
