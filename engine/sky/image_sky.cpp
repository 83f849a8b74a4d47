#include "sky/image_sky.hpp"

#include <stdexcept>

#include "assets/shot_resources.hpp"

namespace lc {

// The image is loaded once per shot (ShotResources).
ImageSky::ImageSky(const Params& p, ShotResources& res) : TextureSky(p.rotate, p.brightness, res.texture(p.file)) {}

PointStarSky::Params ImageSky::real_stars(const Params& p) {
  throw std::invalid_argument(
      "--sky kstars: the sky is lc.sky_image{file = \"" + p.file +
      "\"}, a picture of the shot's own that the real stars would be drawn over (stars in it would be doubled): "
      "to keep it behind them give the shot lc.starfield{catalogue = \"kstars\", background = \"" + p.file +
      "\"}, else leave out --sky (docs/cameras.md)");
}

}  // namespace lc
