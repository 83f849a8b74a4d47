#pragma once
// A shot made for a flat screen, delivered to another (render --camera,
// showcase --camera; docs/cameras.md, "A shot through a dome or a 360
// camera"): its frames through a dome master or a 360-degree camera in
// place of its own, framed from its own camera's orientation.
//   dome: the 180-degree fisheye, its axis pitched dome_pitch above the
//         shot's aim, so what the shot looked at sits 90 - dome_pitch
//         degrees above the dome's front horizon, the sweet spot a seated
//         audience looks at without craning (not the zenith);
//   360:  the whole sphere, its front the shot's heading (yaw) but its
//         horizon level (no pitch, no roll: a viewer in a headset chooses
//         where to look, and a sphere that tilts under them is sickening).
// Square frames for the dome and 2:1 for the sphere, of the shot's height
// unless a size is given.

#include <array>
#include <utility>
#include <variant>

#include "camera/camera.hpp"
#include "camera/delivery_camera.hpp"

namespace lc {

// The dome's axis above the shot's aim, degrees.
inline constexpr double dome_pitch = 55.0;

// The camera `shot_camera` (any kind) is delivered through.
inline CameraSpec delivered(const CameraSpec& shot_camera, DeliveryCamera to) {
  if (to == DeliveryCamera::shot) return shot_camera;
  const auto [yaw, pitch, roll] =
      std::visit([](const auto& p) { return std::array<double, 3>{p.yaw, p.pitch, p.roll}; }, shot_camera);
  if (to == DeliveryCamera::dome) {
    FisheyeCamera::Params dome;
    dome.yaw = yaw;
    dome.pitch = pitch + dome_pitch;
    dome.roll = roll;
    return dome;
  }
  EquirectCamera::Params sphere;
  sphere.yaw = yaw;
  return sphere;
}

// The frame size for `to` when none is given: the shot's own for the
// shot's camera, else square (dome) or 2:1 (360) of the shot's height.
inline std::pair<int, int> delivery_size(DeliveryCamera to, int width, int height) {
  switch (to) {
    case DeliveryCamera::shot: return {width, height};
    case DeliveryCamera::dome: return {height, height};
    case DeliveryCamera::sphere: return {2 * height, height};
  }
  return {width, height};
}

}  // namespace lc
