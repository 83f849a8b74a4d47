#pragma once
// Where the shot-author Lua library (scripts/) is found, so that
// `require "lightcone"` works from a build tree, an install, or anywhere the
// user points LIGHTCONE_SCRIPTS at.

#include <filesystem>
#include <vector>

namespace lc {

// The library directory: $LIGHTCONE_SCRIPTS if set, else <exe>/../share/lightcone/scripts
// if it exists, else the source tree's scripts/ (compiled in).  Throws
// std::runtime_error naming every place looked at when none holds lightcone.lua.
std::filesystem::path library_dir();

// The directories `require` searches for a script: the library, then the
// script's own folder.
std::vector<std::filesystem::path> require_dirs_for(const std::filesystem::path& script);

}  // namespace lc
