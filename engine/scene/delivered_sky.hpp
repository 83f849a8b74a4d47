#pragma once
// The sky a shot is delivered under (render --sky; docs/cameras.md, "A shot
// through a dome or a 360 camera"): its own, or KStars' real stars in its
// place.  Here, above both the cameras and the skies, beside the delivery's
// camera (camera/delivery.hpp).

#include <stdexcept>
#include <string>
#include <variant>

#include "camera/delivery_camera.hpp"
#include "sky/sky.hpp"

namespace lc {

// The sky `shot_sky` is delivered under.  With kstars: a starfield keeps
// all but its catalogue (its generated glow, the fake band's, gives way to
// the real sky's black); the generated stars and the checker, lightcone's
// stand-ins for a sky, give way to the real stars at their rotation and
// brightness.  An image is the shot's own picture, perhaps of stars (the
// real ones would be doubled) or of a Milky Way (which belongs behind
// them): only the shot can say, so it throws std::invalid_argument saying
// how.
inline SkySpec delivered_sky(const SkySpec& shot_sky, DeliverySky to) {
  if (to == DeliverySky::shot) return shot_sky;
  PointStarSky::Params real;
  real.catalogue = StarCatalogue::kstars;
  if (const auto* p = std::get_if<PointStarSky::Params>(&shot_sky)) {
    real = *p;
    real.catalogue = StarCatalogue::kstars;
    if (real.background == "generated") real.background = "none";
  } else if (const auto* p = std::get_if<StarImageSky::Params>(&shot_sky)) {
    real.rotate = p->rotate;
    real.brightness = p->brightness;
  } else if (const auto* p = std::get_if<CheckerSky::Params>(&shot_sky)) {
    real.rotate = p->rotate;
    real.brightness = p->brightness;
  } else if (const auto* p = std::get_if<ImageSky::Params>(&shot_sky)) {
    throw std::invalid_argument(
        "--sky kstars: the sky is lc.sky_image{file = \"" + p->file +
        "\"}, a picture of the shot's own that the real stars would be drawn over (stars in it would be doubled): "
        "to keep it behind them give the shot lc.starfield{catalogue = \"kstars\", background = \"" + p->file +
        "\"}, else leave out --sky (docs/cameras.md)");
  }
  return real;
}

}  // namespace lc
