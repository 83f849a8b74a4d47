#pragma once
// The parameters of the pinhole camera (camera/pinhole.hpp), as a shot gives them
// (lc.camera{...}): plain data with declared fields, apart from the camera
// so that what holds or describes a camera spec (camera/camera_spec.hpp)
// does not include the camera's code.

#include <optional>
#include <string_view>
#include <tuple>

#include "camera/camera_axes.hpp"
#include "camera/stereo.hpp"
#include "core/fields.hpp"

namespace lc {

struct PinholeParams {
  static constexpr std::string_view name = "camera";  // lc.camera{...}
  double fov = 60.0;  // horizontal, degrees (of one eye's picture in stereo)
  StereoLayout stereo = StereoLayout::mono;
  double separation = 1.0;  // M
  double yaw = 0.0, pitch = 0.0, roll = 0.0;
  static constexpr auto fields =
      std::tuple_cat(std::tuple{field("fov", &PinholeParams::fov, std::optional<double>{60.0}, above(0.0), below(180.0),
                                      "horizontal field of view (of each eye's picture, in stereo)", "degrees")},
                     stereo_fields<PinholeParams>(), orientation_fields<PinholeParams>());
};

}  // namespace lc
