#pragma once
// The equirectangular camera (lc.equirect; docs/cameras.md): longitude
// across the image and latitude up it, both linear in pixels: at its
// defaults the whole sphere in a 2:1 frame, a 360-degree video's.  A
// window of the sphere is a smaller span of either.  Directions are
// components on the tetrad's spatial legs, as the pinhole's
// (camera/pinhole.hpp): the image's centre looks along the camera's forward
// after yaw, pitch and roll, longitude grows towards its right and latitude
// towards its up.  With spans L (longitude) and B (latitude),
//   lon = (px / W - 1/2) L,  lat = (1/2 - py / H) B,
//   direction = cos(lat) (cos(lon) forward + sin(lon) right) + sin(lat) up.
// Every image point has a ray.  The formula continues past the frame's
// edges (beyond a pole it reaches over to the other side), which the star
// stage's patches at the edges use; the whole sphere wraps around and over
// its poles (core/image_wrap.hpp).

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "camera/camera_axes.hpp"
#include "camera/camera_sample.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/image_wrap.hpp"
#include "core/tensor.hpp"
#include "image/video_layout.hpp"

namespace lc {

class EquirectCamera {
 public:
  static constexpr std::string_view name = "equirect";  // lc.equirect{...}
  static constexpr bool rays_everywhere = true;
  struct Params {
    double longitude = 360.0;  // the window's span in longitude, degrees
    double latitude = 180.0;   // ... and in latitude
    double yaw = 0.0, pitch = 0.0, roll = 0.0;
    static constexpr auto fields = std::tuple_cat(
        std::tuple{field("longitude", &Params::longitude, std::optional<double>{360.0}, above(0.0), at_most(360.0),
                         "the span of longitude across the image, centred on forward (360: all the way round)",
                         "degrees"),
                   field("latitude", &Params::latitude, std::optional<double>{180.0}, above(0.0), at_most(180.0),
                         "the span of latitude up the image, centred on forward (180: pole to pole)", "degrees")},
        orientation_fields<Params>());
  };

  // Image size in pixels; the parameters' angles are in degrees.
  EquirectCamera(const Params& p, int width, int height)
      : lon_per_px_(p.longitude * degree / width),
        lat_per_px_(p.latitude * degree / height),
        half_width_(0.5 * width),
        half_height_(0.5 * height) {
    axes_ = turned_axes(p.yaw, p.pitch, p.roll);
    wrap_.columns = p.longitude == 360.0;
    wrap_.poles = wrap_.columns && p.latitude == 180.0 && width % 2 == 0;
    if (wrap_.columns && p.latitude == 180.0) layout_.projection = VideoProjection::equirectangular;
  }

  // The ray through the sample's image point, from the observer's own event.
  std::optional<CameraRay> ray(const CameraSample& s) const { return CameraRay{direction(s.px, s.py), {}, s.time}; }

  // The unit direction through image point (px, py), the formula above
  // also beyond the frame's edges.
  Vec3 direction(double px, double py) const {
    const double lon = (px - half_width_) * lon_per_px_, lat = (half_height_ - py) * lat_per_px_;
    const double cl = std::cos(lat), x = cl * std::sin(lon), z = cl * std::cos(lon), y = std::sin(lat);
    Vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = z * axes_.forward[k] + x * axes_.right[k] + y * axes_.up[k];
    return d;
  }

  ImageWrap wrap() const { return wrap_; }
  // The whole sphere is a 360-degree video's; a window is a flat picture
  // to a player.
  VideoLayout video_layout() const { return layout_; }

  // Pixels that are not square (the spans' ratio is not the frame's): a
  // 360-degree frame that is not 2:1.  Players and video sites expect
  // square pixels; the frame is still rendered as asked.
  std::optional<std::string> size_warning() const {
    const double ratio = lon_per_px_ / lat_per_px_;
    if (std::abs(ratio - 1.0) <= 1e-3) return std::nullopt;
    return fmt::format(
        "equirect: the frame's pixels span {:.4g} degrees of longitude but {:.4g} of latitude (not square); a "
        "{}x{}-degree window wants a frame {:.4g} times as wide as it is high (2:1 for the whole sphere)",
        lon_per_px_ / degree, lat_per_px_ / degree, 2 * half_width_ * lon_per_px_ / degree,
        2 * half_height_ * lat_per_px_ / degree, (half_width_ * lon_per_px_) / (half_height_ * lat_per_px_));
  }

  const CameraAxes& axes() const { return axes_; }

 private:
  CameraAxes axes_;
  ImageWrap wrap_;
  VideoLayout layout_;
  double lon_per_px_, lat_per_px_, half_width_, half_height_;
};

}  // namespace lc
