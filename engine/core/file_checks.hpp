#pragma once
// Checks on files the engine reads for a script (modules, sky images): a
// script names them, so a link or a FIFO could lead anywhere.

#include <sys/types.h>

#include <filesystem>

namespace lc {

// Whether `path` lies inside the folder `dir`; both must be canonical
// (absolute, links and '..' resolved), as std::filesystem::canonical gives.
bool is_within(const std::filesystem::path& path, const std::filesystem::path& dir);

// How a message names a file of this st_mode that is no regular file: "a
// FIFO", "a directory", "a character device", ...
const char* file_kind(mode_t mode);

}  // namespace lc
