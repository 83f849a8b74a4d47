#pragma once
// A shot script, loaded once into its own sandbox: the frame-independent
// settings, and frame(i) -> SceneSpec by calling the script's frame
// function.  Not thread-safe (one Lua state); every thread or rank that
// needs scenes loads its own Shot — scripts are deterministic, so all agree.

#include <filesystem>
#include <memory>
#include <vector>

#include "lua/sandbox.hpp"
#include "scene/scene_spec.hpp"

namespace lc {

class Shot {
 public:
  // Runs the script (sandboxed) and reads the shot table it returns.  Throws
  // lua::ScriptError / lua::FieldError naming the file and line or field.
  explicit Shot(const std::filesystem::path& file, lua::SandboxLimits limits = {});
  ~Shot();

  const ShotInfo& info() const { return info_; }
  const std::filesystem::path& file() const { return file_; }

  // The scene of frame i (0-based, < info().frames).  Errors name the file,
  // the frame and the field.
  SceneSpec frame(int i);

  // The script and every module it required (for hashing a shot's inputs).
  std::vector<std::filesystem::path> loaded_files() const;
  // Where the shot's assets (sky images) are looked for: its own folder,
  // then the project's shots/ folder.
  std::vector<std::filesystem::path> asset_dirs() const;

 private:
  std::filesystem::path file_;
  lua::Sandbox sandbox_;
  ShotInfo info_;
  int frame_ref_;  // registry reference to the frame function
};

}  // namespace lc
