// A direct reader for the EXR layout lightcone's own writer makes
// (write_exr): one part of scanlines, FLOAT channels R, G, B and perhaps A,
// stored raw or zip-compressed, the data window the display window at the
// origin.  It parses that layout itself and inflates with libdeflate instead
// of going through OpenEXR's general framebuffer machinery and zlib, which
// made reading a frame back the largest share of `develop` and of the
// writer's check (docs/performance.md).  Every other EXR is OpenImageIO's.
#pragma once

#include <filesystem>
#include <optional>

#include "image/frame_image.hpp"

namespace lc {

// Input: any path.  Output: the frame (rgb interleaved, alpha when the file
// has A, no layers) when the file is in the layout above and reads whole,
// every block where the offset table puts it, every zip block inflating to
// exactly its size with its checksum right.  Otherwise nullopt: another
// layout, or a file it cannot read (missing, cut short, damaged), which
// read_exr then gives to OpenImageIO, so such a file gets OpenImageIO's
// verdict and message as before.  Never throws for the file's content.
std::optional<FrameImage> read_rgb_exr(const std::filesystem::path& path);

}  // namespace lc
