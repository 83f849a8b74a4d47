#pragma once
// lc.sky_stars{...}: the procedural star field (image/generated_stars.hpp) made in
// memory for any seed, as an equirectangular texture `resolution` pixels
// wide.

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/color.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "image/texture.hpp"
#include "sky/point_star_sky.hpp"
#include "sky/texture_sky.hpp"

namespace lc {

class ShotResources;

class StarImageSky : public TextureSky {
 public:
  static constexpr std::string_view name = "sky_stars";
  struct Params {
    std::uint32_t seed = 1;
    int resolution = 2048;
    double rotate = 0.0, brightness = 0.0;
    static constexpr auto fields = std::tuple{
        field("seed", &Params::seed, std::optional<std::uint32_t>{1}, at_least(0), at_most(2147483647),
              "the catalogue's seed"),
        field("resolution", &Params::resolution, std::optional<int>{2048}, at_least(64), at_most(max_star_field_width),
              "the texture's width (its height is half)", "pixels"),
        field("rotate", &Params::rotate, std::optional<double>{0.0}, std::nullopt, std::nullopt,
              "added to the longitude", "degrees"),
        field("brightness", &Params::brightness, std::optional<double>{0.0}, at_least(-64.0), at_most(64.0),
              "the texture's light times 2^brightness (for scenes in physical units: docs/light.md)", "stops"),
    };
  };
  static std::vector<std::string> assets(const Params&) { return {}; }
  // What render --sky kstars delivers it as: the generated stars stand in
  // for the real ones, which replace them at their rotation and brightness.
  static PointStarSky::Params real_stars(const Params& p) { return real_stars_at(p.rotate, p.brightness); }

  StarImageSky(const Params& p, ShotResources& res);
};

}  // namespace lc
