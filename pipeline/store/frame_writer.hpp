#pragma once
// Writes a frame's files so that a final name only ever shows a complete,
// readable file: each file goes to a DurableFile's temporary, is read back
// (the image writers do not always notice a failed write: on a full disk a
// PNG can come out empty without an error) and only then committed.  The
// frame store's cleanup finds the temporaries of a killed render by their
// name (is_temporary_name).  The names are the frame store's own
// (DurableFile's FinalName::own): whatever is under one, a planted link
// included, is replaced, and nothing outside the folder is written.

#include <filesystem>

#include "image/look.hpp"
#include "image/image.hpp"

namespace lc::farm {

// Writes `image` as `exr` (linear float, with `metadata`) and `png` (sRGB
// of the image through `look`, `png_depth` bits), each read back, and commits both together: after it returns both
// survive a crash, and if it throws (std::runtime_error naming the file)
// neither final name has changed unless the failure came in the renames
// themselves.  No temporary is left behind.
void write_frame_files(const std::filesystem::path& exr, const std::filesystem::path& png, const FrameImage& image,
                       const ImageMetadata& metadata, const Look& look,
                       PngDepth png_depth = PngDepth::eight);

// The same for a PNG alone (a preview, a developed frame).
void write_png_file(const std::filesystem::path& png, const FrameImage& image, const Look& look,
                    PngDepth png_depth = PngDepth::eight);

}  // namespace lc::farm
