#include "assets/shot_resources.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "image/generated_stars.hpp"
#include "assets/asset_path.hpp"
#include "worldline/worldline.hpp"

namespace lc {

ShotResources::ShotResources(std::vector<std::filesystem::path> asset_dirs, std::size_t budget)
    : asset_dirs_(std::move(asset_dirs)), budget_(budget) {}

template <class T, class Make>
std::shared_ptr<const T> ShotResources::get(const std::string& key, const char* what, Make&& make) {
  {
    std::lock_guard lock(mutex_);
    if (auto it = entries_.find(key); it != entries_.end()) {
      it->second.last_use = ++uses_;
      return std::static_pointer_cast<const T>(it->second.value);
    }
  }
  // Made outside the lock; a racing duplicate is harmless (the same result).
  auto [value, bytes] = make();
  std::lock_guard lock(mutex_);
  if (auto it = entries_.find(key); it != entries_.end()) return std::static_pointer_cast<const T>(it->second.value);
  while (bytes_ + bytes > budget_) {
    auto lru = entries_.end();
    for (auto it = entries_.begin(); it != entries_.end(); ++it)
      if (it->second.value.use_count() == 1 && (lru == entries_.end() || it->second.last_use < lru->second.last_use))
        lru = it;
    if (lru == entries_.end())
      throw std::invalid_argument(fmt::format(
          "{} ({:.0f} MiB) does not fit beside the worldlines, sky images and star fields in use ({:.0f} MiB): a "
          "process holds at most {:.0f} MiB of them (docs/shots.md, Limits)",
          what, bytes / 1048576.0, bytes_ / 1048576.0, budget_ / 1048576.0));
    bytes_ -= lru->second.bytes;
    entries_.erase(lru);
  }
  bytes_ += bytes;
  entries_[key] = Entry{value, bytes, ++uses_};
  return value;
}

std::shared_ptr<const Worldline> ShotResources::worldline(const WorldlineSpec& spec) {
  return get<Worldline>("worldline " + spec.key(), "a worldline", [&] {
    auto w = std::make_shared<const Worldline>(Worldline::integrate(spec));
    return std::pair{w, w->bytes()};
  });
}

std::shared_ptr<const Texture> ShotResources::texture(const std::filesystem::path& file) {
  const std::filesystem::path found = resolve_sky_image(file, asset_dirs_);
  {
    std::lock_guard lock(mutex_);
    files_.insert(found);
  }
  return get<Texture>("texture " + found.string(), "a sky image", [&] {
    auto t = std::make_shared<const Texture>(Texture::load(found, max_sky_image_pixels));
    return std::pair{t, t->bytes()};
  });
}

std::shared_ptr<const Texture> ShotResources::starfield(std::uint32_t seed, int width) {
  return get<Texture>(fmt::format("stars {} {}", seed, width), "a star field", [&] {
    FrameImage img = render_starfield(width, width / 2, seed);
    auto t = std::make_shared<const Texture>(Texture::from_pixels(img.width, img.height, std::move(img.rgb)));
    return std::pair{t, t->bytes()};
  });
}

std::shared_ptr<const Texture> ShotResources::sky_glow(std::uint32_t seed, int width) {
  return get<Texture>(fmt::format("glow {} {}", seed, width), "a sky's glow", [&] {
    FrameImage img = render_sky_glow(width, width / 2, seed);
    auto t = std::make_shared<const Texture>(Texture::from_pixels(img.width, img.height, std::move(img.rgb)));
    return std::pair{t, t->bytes()};
  });
}

std::shared_ptr<const StarField> ShotResources::star_field(const std::string& key,
                                                           const std::function<StarField()>& make) {
  return get<StarField>("point stars " + key, "a sky's point stars", [&] {
    auto f = std::make_shared<const StarField>(make());
    return std::pair{f, f->bytes()};
  });
}

std::shared_ptr<const BlackbodyColors> ShotResources::blackbody_colors(double reference) {
  return get<BlackbodyColors>(fmt::format("blackbody {:a}", reference), "blackbody colours", [&] {
    auto c = std::make_shared<const BlackbodyColors>(reference);
    return std::pair{c, c->bytes()};
  });
}

std::shared_ptr<const SpectralShift> ShotResources::spectral_shift() {
  return get<SpectralShift>("spectral shift", "texture spectra", [] {
    auto s = std::make_shared<const SpectralShift>();
    return std::pair{s, s->bytes()};
  });
}

std::vector<std::filesystem::path> ShotResources::files() const {
  std::lock_guard lock(mutex_);
  return {files_.begin(), files_.end()};
}

std::size_t ShotResources::bytes() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

}  // namespace lc
