#include "camera/delivery.hpp"

#include <array>
#include <variant>

#include "camera/camera_params.hpp"

namespace lc {

static_assert(EquirectParams{}.separation == default_ods_separation,
              "--separation's default is the equirect's own");

CameraSpec delivered(const CameraSpec& shot_camera, const Delivery& to) {
  if (to.camera == DeliveryCamera::shot) return shot_camera;
  const auto [yaw, pitch, roll] =
      std::visit([](const auto& p) { return std::array<double, 3>{p.yaw, p.pitch, p.roll}; }, shot_camera.kinds());
  if (to.camera == DeliveryCamera::dome) {
    FisheyeParams dome;
    dome.yaw = yaw;
    dome.pitch = pitch + (90.0 - to.dome_elevation);
    dome.roll = roll;
    dome.tilt = to.dome_tilt;
    return dome;
  }
  EquirectParams sphere;
  sphere.yaw = yaw;
  if (to.camera == DeliveryCamera::ods) {
    sphere.stereo = StereoLayout::top_bottom;
    sphere.separation = to.separation;
  }
  return sphere;
}

}  // namespace lc
