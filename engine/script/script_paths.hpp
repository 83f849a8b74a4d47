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

// The project's shots/ folder (beside the library's folder): the shipped
// shots, their textures, and the modules `require "lightcone.shots.NAME"`
// reads.
std::filesystem::path shots_dir();

// The prefix of the module names that are the shipped shots.
inline constexpr const char* kShotsModulePrefix = "lightcone.shots";

// The directories `require` searches for a script: the library, then the
// script's own folder.
std::vector<std::filesystem::path> require_dirs_for(const std::filesystem::path& script);

}  // namespace lc
