#pragma once
// lc.sky_image{file = ...}: an equirectangular image at infinity (longitude 0
// at the left edge, growing to the right; the top edge is +z), in any
// format OpenImageIO reads.  lc.starfield{} is this with the star field
// that ships with lightcone.

#include <cmath>
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

class ImageSky : public TextureSky {
 public:
  static constexpr std::string_view name = "sky_image";
  struct Params {
    std::string file;
    double rotate = 0.0, brightness = 0.0;
    static constexpr auto fields = std::tuple{
        field("file", &Params::file, std::optional<std::string>{}, std::nullopt, std::nullopt,
              "the image, relative to the shot's folder or the project's shots/"),
        field("rotate", &Params::rotate, std::optional<double>{0.0}, std::nullopt, std::nullopt,
              "added to the longitude", "degrees"),
        field("brightness", &Params::brightness, std::optional<double>{0.0}, at_least(-64.0), at_most(64.0),
              "the texture's light times 2^brightness (for scenes in physical units: docs/light.md)", "stops"),
    };
  };
  // The file a frame with this sky reads (resolved as resolve_sky_image says).
  static std::vector<std::string> assets(const Params& p) { return {p.file}; }
  // What render --sky kstars delivers it as: nothing.  The image is the
  // shot's own picture, perhaps of stars (the real ones would be doubled)
  // or of a Milky Way (which belongs behind them): only the shot can say,
  // so this throws std::invalid_argument saying how.
  [[noreturn]] static PointStarSky::Params real_stars(const Params& p);

  ImageSky(const Params& p, ShotResources& res);
};

}  // namespace lc
