#pragma once
// FrameScene (plain data from the script) -> Scene (ready to trace): builds
// the spacetime in the outgoing Kerr–Schild chart, the observer's event and
// tetrad, the camera, and the objects; integrates worldlines and loads
// textures once per shot through ShotResources.

#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "render/scene.hpp"

namespace lc {

// Per-shot caches shared by all frames (thread-safe).
class ShotResources {
 public:
  // Texture paths are resolved against these folders in order (the shot's
  // own folder first), as resolve_sky_image (scene/asset_path.hpp) says.
  explicit ShotResources(std::vector<std::filesystem::path> asset_dirs = {});
  std::shared_ptr<const Worldline> worldline(const WorldlineSpec& spec);
  std::shared_ptr<const Texture> texture(const std::filesystem::path& file);
  // The procedural star field (render_starfield), made once per seed and size.
  std::shared_ptr<const Texture> starfield(std::uint32_t seed, int width);
  // Every file loaded (textures), for hashing a shot's inputs.
  std::vector<std::filesystem::path> files() const;

 private:
  std::vector<std::filesystem::path> asset_dirs_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<const Worldline>> worldlines_;
  std::map<std::filesystem::path, std::shared_ptr<const Texture>> textures_;
  std::map<std::pair<std::uint32_t, int>, std::shared_ptr<const Texture>> starfields_;
};

// Throws std::invalid_argument for a scene that cannot exist (an observer
// inside a horizon or a static one in the ergoregion, a worldline from a
// different spacetime, ...).
Scene build_scene(const FrameScene& fs, int width, int height, ShotResources& resources,
                  const RayOptions& rays = RayOptions{});

}  // namespace lc
