#pragma once
// The parameters of the fisheye camera (camera/fisheye.hpp), as a shot gives them
// (lc.fisheye{...}): plain data with declared fields, apart from the camera
// so that what holds or describes a camera spec (camera/camera_spec.hpp)
// does not include the camera's code.

#include <optional>
#include <string_view>
#include <tuple>

#include "camera/camera_axes.hpp"
#include "core/fields.hpp"

namespace lc {

struct FisheyeParams {
  static constexpr std::string_view name = "fisheye";  // lc.fisheye{...}
  double full_angle = 180.0;  // Lua `field`: the disc's full angle, degrees
  double tilt = 0.0;     // the dome's forward tilt, degrees
  double yaw = 0.0, pitch = 0.0, roll = 0.0;
  static constexpr auto fields = std::tuple_cat(
      std::tuple{field("field", &FisheyeParams::full_angle, std::optional<double>{180.0}, at_least(90.0), at_most(360.0),
                       "the full angle across the image disc (180: a hemisphere, a dome master)", "degrees"),
                 field("tilt", &FisheyeParams::tilt, std::optional<double>{0.0}, at_least(0.0), at_most(90.0),
                       "the dome's tilt: the view axis turned from forward towards down by this much, so a "
                       "shot framed for a level dome sits the same above a tilted dome's front horizon",
                       "degrees")},
      orientation_fields<FisheyeParams>());
};

}  // namespace lc
