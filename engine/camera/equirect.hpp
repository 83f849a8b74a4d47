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
// In stereo (top-bottom: camera/stereo.hpp) W x H is one eye's picture and
// the eyes are omnidirectional stereo's (ODS): for each viewing direction
// the eye sits on a circle of radius separation / 2 about the observer in
// the camera's forward-right plane, at right angles to the direction's
// longitude (left eye to the left), so every ray is tangent to the circle;
// the radius shrinks linearly to 0 between latitudes pole_merge_from and
// pole_merge_to (Blender Cycles' pole merge), so the poles, where every
// longitude meets, show no seam of disagreeing eyes.

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "camera/camera_axes.hpp"
#include "camera/equirect_params.hpp"
#include "camera/camera_sample.hpp"
#include "camera/stereo.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/image_wrap.hpp"
#include "core/tensor.hpp"
#include "image/video_layout.hpp"

namespace lc {

class EquirectCamera {
 public:
  using Params = EquirectParams;
  static constexpr std::string_view name = Params::name;  // lc.equirect{...}
  static constexpr bool rays_everywhere = true;
  // Where ODS's eyes start merging towards the poles, and where they have
  // met (Cycles' defaults), radians.
  static constexpr double pole_merge_from = 60.0 * degree, pole_merge_to = 75.0 * degree;

  // Image size in pixels; the parameters' angles are in degrees.
  EquirectCamera(const Params& p, int width, int height)
      : frame_(p.stereo, width, height),
        lon_per_px_(p.longitude * degree / frame_.eye_width()),
        lat_per_px_(p.latitude * degree / frame_.eye_height()),
        half_width_(0.5 * frame_.eye_width()),
        half_height_(0.5 * frame_.eye_height()),
        half_separation_(p.stereo == StereoLayout::mono ? 0.0 : 0.5 * p.separation) {
    axes_ = turned_axes(p.yaw, p.pitch, p.roll);
    wrap_.columns = p.longitude == 360.0;
    wrap_.poles = wrap_.columns && p.latitude == 180.0 && frame_.eye_width() % 2 == 0;
    if (wrap_.columns && p.latitude == 180.0) layout_.projection = VideoProjection::equirectangular;
    layout_.stereo = p.stereo;
  }

  // The ray through the sample's image point, from the observer's own
  // event, or in stereo from the eye of the point's picture on the ODS
  // circle.
  std::optional<CameraRay> ray(const CameraSample& s) const {
    if (frame_.layout() == StereoLayout::mono) return CameraRay{direction(s.px, s.py), {}, s.time};
    const EyePoint v = frame_.view(s.px, s.py);
    CameraRay r{direction(v.px, v.py), {}, s.time};
    const double lon = (v.px - half_width_) * lon_per_px_, lat = std::abs((half_height_ - v.py) * lat_per_px_);
    const double merge = std::clamp((pole_merge_to - lat) / (pole_merge_to - pole_merge_from), 0.0, 1.0);
    const double radius = v.eye * half_separation_ * merge, c = std::cos(lon), s_ = std::sin(lon);
    for (int k = 0; k < 3; ++k) r.eye[k] = radius * (c * axes_.right[k] - s_ * axes_.forward[k]);
    return r;
  }

  // The unit direction through image point (px, py) of an eye's picture
  // (the frame, in mono), the formula above also beyond its edges.
  Vec3 direction(double px, double py) const {
    const double lon = (px - half_width_) * lon_per_px_, lat = (half_height_ - py) * lat_per_px_;
    const double cl = std::cos(lat), x = cl * std::sin(lon), z = cl * std::cos(lon), y = std::sin(lat);
    Vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = z * axes_.forward[k] + x * axes_.right[k] + y * axes_.up[k];
    return d;
  }

  // Each eye's picture wraps (top-bottom stereo keeps every row in one).
  ImageWrap wrap() const { return wrap_; }
  std::vector<EyePicture> pictures() const { return frame_.pictures(); }
  // The whole sphere is a 360-degree video's; a window is a flat picture
  // to a player.  Its stereo layout, in stereo.
  VideoLayout video_layout() const { return layout_; }

  // Pixels that are not square (the spans' ratio is not each picture's):
  // a 360-degree frame that is not 2:1, or a top-bottom ODS frame that is
  // not square.  Players and video sites expect square pixels; the frame
  // is still rendered as asked.  Says the size the frame should have at
  // its width.
  std::optional<std::string> size_warning() const {
    const double ratio = lon_per_px_ / lat_per_px_;
    if (std::abs(ratio - 1.0) <= 1e-3) return std::nullopt;
    const double lon_span = 2 * half_width_ * lon_per_px_ / degree, lat_span = 2 * half_height_ * lat_per_px_ / degree;
    const int width = frame_.eye_width(), picture_height = static_cast<int>(std::lround(width * lat_span / lon_span));
    const bool stereo = frame_.layout() == StereoLayout::top_bottom;
    return fmt::format(
        "equirect: the {}pixels span {:.4g} degrees of longitude but {:.4g} of latitude (not square); a {:.4g}x{:.4g}-"
        "degree window wants {} {:.4g} times as wide as it is high: a {}x{} frame at this width{}",
        stereo ? "eyes' pictures' " : "frame's ", lon_per_px_ / degree, lat_per_px_ / degree, lon_span, lat_span,
        stereo ? "each eye's picture" : "a frame", lon_span / lat_span, width, stereo ? 2 * picture_height : picture_height,
        stereo ? " (the two pictures one above the other)" : "");
  }

  const CameraAxes& axes() const { return axes_; }

 private:
  CameraAxes axes_;
  StereoFrame frame_;
  ImageWrap wrap_;
  VideoLayout layout_;
  double lon_per_px_, lat_per_px_, half_width_, half_height_, half_separation_;
};

}  // namespace lc
