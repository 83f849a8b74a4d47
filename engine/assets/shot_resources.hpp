#pragma once
// What a shot makes once and every frame shares: integrated worldlines,
// loaded sky images, generated star fields, point stars, within a memory
// budget.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "image/texture.hpp"
#include "light/blackbody.hpp"
#include "light/spectral_shift.hpp"
#include "stars/star_field.hpp"

namespace lc {

// Declared only: a worldline's spec holds the spacetime, and the skies and
// disks that include this header for their images need no spacetime
// (docs/architecture.md, "What a new kind rebuilds").
class Worldline;        // worldline/worldline.hpp
struct WorldlineSpec;   // worldline/worldline_spec.hpp

// Per-shot caches shared by all frames (thread-safe): worldlines
// integrated, sky images loaded and star fields made once, however many
// frames use them.  They stay within `budget` bytes: to make room, those no
// scene holds any more are released, least recently used first; what the
// scenes in use hold at once beyond the budget is refused.
class ShotResources {
 public:
  // Texture paths are resolved against these folders in order (the shot's
  // own folder first), as resolve_sky_image (assets/asset_path.hpp) says.
  explicit ShotResources(std::vector<std::filesystem::path> asset_dirs = {},
                         std::size_t budget = shot_resource_budget);
  std::shared_ptr<const Worldline> worldline(const WorldlineSpec& spec);
  std::shared_ptr<const Texture> texture(const std::filesystem::path& file);
  // The procedural star field (render_starfield), made once per seed and size.
  std::shared_ptr<const Texture> starfield(std::uint32_t seed, int width);
  // The procedural sky's glow without its stars (render_sky_glow), made once
  // per seed and size.
  std::shared_ptr<const Texture> sky_glow(std::uint32_t seed, int width);
  // A sky's point stars under `key` (what they were made from), made by
  // make() on first use.
  std::shared_ptr<const StarField> star_field(const std::string& key, const std::function<StarField()>& make);
  // Blackbody colours with luminance 1 at `reference` K, made once per
  // reference (a table of ~50 KB that takes ~10 ms to make).
  std::shared_ptr<const BlackbodyColors> blackbody_colors(double reference);
  // The spectra textures are seen shifted through (a table of ~40 KB that
  // takes ~30 ms to make).
  std::shared_ptr<const SpectralShift> spectral_shift();
  // Every file loaded (textures), for hashing a shot's inputs.
  std::vector<std::filesystem::path> files() const;
  // Bytes held now.
  std::size_t bytes() const;

 private:
  struct Entry {
    std::shared_ptr<const void> value;
    std::size_t bytes = 0;
    std::uint64_t last_use = 0;
  };
  // The entry under `key`, made by make() -> {shared_ptr<const T>, bytes}
  // (outside the lock) on first use.  Throws std::invalid_argument when it
  // does not fit beside what is in use.
  template <class T, class Make>
  std::shared_ptr<const T> get(const std::string& key, const char* what, Make&& make);

  std::vector<std::filesystem::path> asset_dirs_;
  std::size_t budget_;
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
  std::size_t bytes_ = 0;
  std::uint64_t uses_ = 0;
  std::set<std::filesystem::path> files_;
};

}  // namespace lc
