#include "delivery_flags.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>

#include "sky/point_star_sky.hpp"

namespace lc {

namespace {

// A dome's angle (--dome-tilt, --dome-elevation) given only with --camera
// dome, within [0, max_dome_angle]; `what` says what the angle is for the
// message.  Returns `fallback` when the flag is not given.
double dome_angle(const char* flag, std::optional<double> value, double fallback, DeliveryCamera camera,
                  const char* what) {
  if (!value) return fallback;
  if (camera != DeliveryCamera::dome)
    throw std::invalid_argument(
        fmt::format("{} {}: only with --camera dome (it sets {}; docs/cameras.md)", flag, *value, what));
  if (!(*value >= 0.0 && *value <= max_dome_angle))
    throw std::invalid_argument(fmt::format("{} {}: must be between 0 and {:g} degrees ({})", flag, *value,
                                            max_dome_angle, what));
  return *value;
}

}  // namespace

Delivery delivery_from_flags(const DeliveryFlags& flags) {
  Delivery out;
  const auto camera = delivery_named(flags.camera);
  if (!camera) throw std::invalid_argument(fmt::format("--camera {}: expected shot, dome, 360 or ods", flags.camera));
  out.camera = *camera;
  out.dome_tilt = dome_angle("--dome-tilt", flags.dome_tilt, default_dome_tilt, out.camera,
                             "the dome's forward tilt, 0 for a level dome, 15 the nominal tilted one");
  out.dome_elevation =
      dome_angle("--dome-elevation", flags.dome_elevation, default_dome_elevation, out.camera,
                 "how high above the dome's front horizon the shot's subject sits, 0 on it, 90 at the zenith");
  if (flags.separation) {
    if (out.camera != DeliveryCamera::ods)
      throw std::invalid_argument(fmt::format(
          "--separation {}: only with --camera ods (the distance between the eyes of omnidirectional stereo; a "
          "shot's own stereo camera sets its own; docs/cameras.md)",
          *flags.separation));
    if (!(*flags.separation > 0.0) || !std::isfinite(*flags.separation))
      throw std::invalid_argument(
          fmt::format("--separation {}: must be greater than 0 (the distance between the eyes, in M)", *flags.separation));
    out.separation = *flags.separation;
  }
  if (flags.sky == name_of(DeliverySky::kstars)) {
    out.sky = DeliverySky::kstars;
    // Checked here, before any frame, in the words of the flag (the
    // catalogue's own check speaks of a shot's `catalogue` field).
    const std::string file = kstars_catalogue_path();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec))
      throw std::invalid_argument(fmt::format(
          "--sky kstars reads KStars' star catalogue {}, which is not {}: install Debian's kstars-data (sudo "
          "apt-get install kstars-data), or name a copy of its stars.dat in LIGHTCONE_STAR_CATALOGUE (docs/stars.md)",
          file, std::filesystem::exists(file, ec) ? "a regular file" : "there"));
  } else if (flags.sky != name_of(DeliverySky::shot)) {
    throw std::invalid_argument(fmt::format("--sky {}: expected shot or kstars", flags.sky));
  }
  return out;
}

}  // namespace lc
