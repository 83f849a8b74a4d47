#pragma once
// A structural check of a PNG file as it lies on disk: the signature, every
// chunk whole with its CRC right (ISO/IEC 15948, section 5.3), IHDR first
// with the expected size, IDAT present and IEND last with nothing after it.
// What a writer needs to know of the file it just wrote (cut short by a full
// disk, a byte changed on the way) at a fraction of decoding it.

#include <filesystem>

namespace lc {

// Throws std::runtime_error saying what is wrong (not naming the file: the
// caller does).
void check_png_file(const std::filesystem::path& path, int width, int height);

}  // namespace lc
