#pragma once
// The parameters of the equirectangular camera (camera/equirect.hpp), as a shot gives them
// (lc.equirect{...}): plain data with declared fields, apart from the camera
// so that what holds or describes a camera spec (camera/camera_spec.hpp)
// does not include the camera's code.

#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include "camera/camera_axes.hpp"
#include "camera/stereo.hpp"
#include "core/fields.hpp"

namespace lc {

struct EquirectParams {
  static constexpr std::string_view name = "equirect";  // lc.equirect{...}
  double longitude = 360.0;  // the window's span in longitude, degrees
  double latitude = 180.0;   // ... and in latitude
  StereoLayout stereo = StereoLayout::mono;
  double separation = 1.0;  // M
  double yaw = 0.0, pitch = 0.0, roll = 0.0;
  static constexpr auto fields = std::tuple_cat(
      std::tuple{field("longitude", &EquirectParams::longitude, std::optional<double>{360.0}, above(0.0), at_most(360.0),
                       "the span of longitude across the image, centred on forward (360: all the way round)",
                       "degrees"),
                 field("latitude", &EquirectParams::latitude, std::optional<double>{180.0}, above(0.0), at_most(180.0),
                       "the span of latitude up the image, centred on forward (180: pole to pole)", "degrees")},
      std::tuple{field("stereo", &EquirectParams::stereo, std::optional<StereoLayout>{StereoLayout::mono}, std::nullopt,
                       std::nullopt,
                       "mono (one eye) or top-bottom: omnidirectional stereo, the left eye's sphere above the "
                       "right's (side-by-side is refused: a 4:1 sphere no video site takes)"),
                 separation_field<EquirectParams>()},
      orientation_fields<EquirectParams>());
  // ODS is delivered top-bottom (the 360-degree video sites' layout); a
  // side-by-side sphere would be 4:1.
  void validate() const {
    if (stereo == StereoLayout::side_by_side)
      throw std::invalid_argument("stereo 'side-by-side' is not offered for the equirect: omnidirectional stereo is "
                                  "delivered top-bottom (stereo = \"top-bottom\", a square frame for the whole sphere)");
  }
};

}  // namespace lc
