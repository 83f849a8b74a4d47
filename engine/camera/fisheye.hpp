#pragma once
// The fisheye camera, equidistant ("angular", the fulldome standard's dome
// master; docs/cameras.md): the angle of a ray from the view axis is
// proportional to its image point's distance from the image centre, the
// disc of the field touching the shorter sides of the frame (all four of a
// square one), and no ray outside the disc.  Directions are components on
// the tetrad's spatial legs, as the pinhole's (camera/pinhole.hpp): the
// view axis is the camera's forward after yaw, pitch and roll, then turned
// by the dome's tilt towards the camera's down; "up" in the image (towards
// the top edge) is the camera's up.  With R = min(W, H) / 2,
//   x = (px - W/2) / R,  y = (H/2 - py) / R,  rho = sqrt(x^2 + y^2),
//   angle from the axis = rho * field / 2   (rho <= 1: a ray; else none),
//   direction = cos(angle) forward + sin(angle) (x right + y up) / rho.

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <tuple>

#include "camera/camera_axes.hpp"
#include "camera/fisheye_params.hpp"
#include "camera/camera_sample.hpp"
#include "camera/stereo.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/image_wrap.hpp"
#include "core/tensor.hpp"
#include "image/video_layout.hpp"

namespace lc {

class FisheyeCamera {
 public:
  using Params = FisheyeParams;
  static constexpr std::string_view name = Params::name;  // lc.fisheye{...}
  static constexpr bool rays_everywhere = false;  // none outside the disc

  // Image size in pixels; the parameters' angles are in degrees.
  FisheyeCamera(const Params& p, int width, int height)
      : half_field_(0.5 * p.full_angle * degree),
        cx_(0.5 * width),
        cy_(0.5 * height),
        inv_radius_(2.0 / std::min(width, height)),
        width_(width),
        height_(height) {
    axes_ = turned_axes(p.yaw, p.pitch, p.roll);
    // The tilt turns the axis (forward) towards down, about the camera's right.
    const double c = std::cos(p.tilt * degree), s = std::sin(p.tilt * degree);
    const Vec3 f = axes_.forward, u = axes_.up;
    for (int k = 0; k < 3; ++k) {
      axes_.forward[k] = c * f[k] - s * u[k];
      axes_.up[k] = c * u[k] + s * f[k];
    }
  }

  // The ray through the sample's image point, from the observer's own
  // event; none outside the disc.
  std::optional<CameraRay> ray(const CameraSample& s) const {
    const double x = (s.px - cx_) * inv_radius_, y = (cy_ - s.py) * inv_radius_;
    if (x * x + y * y > 1.0) return std::nullopt;
    return CameraRay{along(x, y), {}, s.time};
  }

  // The direction through image point (px, py), continued past the disc by
  // the same projection (up to the direction opposite the axis): the star
  // stage's patches of sky at the disc's edge reach a little beyond it.
  Vec3 direction(double px, double py) const { return along((px - cx_) * inv_radius_, (cy_ - py) * inv_radius_); }

  ImageWrap wrap() const { return {}; }  // an image with edges
  VideoLayout video_layout() const { return {}; }  // a flat picture
  std::vector<EyePicture> pictures() const { return {{0, 0, 0, width_, height_}}; }  // one eye
  const CameraAxes& axes() const { return axes_; }

 private:
  // The unit direction at disc coordinates (x, y) (1 at the disc's edge).
  Vec3 along(double x, double y) const {
    const double rho = std::hypot(x, y);
    if (rho == 0.0) return axes_.forward;
    const double angle = std::min(rho * half_field_, pi);
    const double c = std::cos(angle), s = std::sin(angle) / rho;
    Vec3 d;
    for (int k = 0; k < 3; ++k) d[k] = c * axes_.forward[k] + s * (x * axes_.right[k] + y * axes_.up[k]);
    return d;
  }

  CameraAxes axes_;
  double half_field_, cx_, cy_, inv_radius_;
  int width_, height_;
};

}  // namespace lc
