#pragma once
// The command line's delivery flags (render's and trace's --camera,
// --dome-tilt, --dome-elevation, --separation, --sky; docs/cameras.md, "A
// shot through a dome or a 360 camera") and the delivery they ask for.

#include <optional>
#include <string>

#include "camera/delivery_camera.hpp"

namespace lc {

struct DeliveryFlags {
  std::string camera = "shot";               // --camera: shot, dome, 360 or ods
  std::optional<double> dome_tilt;           // --dome-tilt, degrees (dome only)
  std::optional<double> dome_elevation;      // --dome-elevation, degrees (dome only)
  std::optional<double> separation;          // --separation, M (ods only)
  std::string sky = "shot";                  // --sky: shot or kstars
};

// The delivery the flags ask for.  Throws std::invalid_argument naming the
// flag: an unknown camera or sky, a dome's angle outside 0 to 90, a
// separation not above 0, a dome's flag without --camera dome or
// --separation without --camera ods, or --sky kstars where the catalogue
// is not installed (saying which package to install).
Delivery delivery_from_flags(const DeliveryFlags& flags);

}  // namespace lc
