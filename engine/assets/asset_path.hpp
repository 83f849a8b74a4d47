#pragma once
// Which files a shot may name (sky images), and where they are read from.

#include <filesystem>
#include <vector>

namespace lc {

// The real path (links resolved) of the sky image `file` that a shot names
// in lc.sky_image{file = ...}. A shot reads only regular files inside its
// asset folders (`dirs`: Shot::asset_dirs, its own folder, then the
// project's shots/ folder): `file` must be a relative path; the first
// folder holding it is taken, and the file there must, links resolved, lie
// inside one of the folders and be a regular file (a FIFO or /dev/zero
// would block or never end whatever reads it). Only names and file types
// are looked at: nothing is opened. Throws std::invalid_argument naming the
// file and what is wrong.
std::filesystem::path resolve_sky_image(const std::filesystem::path& file,
                                        const std::vector<std::filesystem::path>& dirs);

}  // namespace lc
