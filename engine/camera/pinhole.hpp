#pragma once
// The pinhole camera: the view docs/architecture.md's camera convention
// describes, in an observer's tetrad.  Directions are components on the
// tetrad's spatial legs (1, 2, 3); the default view looks "at the hole":
// forward = -e_1, up = -e_2, right = e_3, then turned by yaw (forward
// towards right), pitch (forward towards up) and roll (up towards right).
// Pixel (i, j) (i from the left, j from the top, centres at i + 1/2, j + 1/2)
// looks along normalize(forward + x right + y up) with
// x = (2 px / W - 1) tan(fov/2), y = (1 - 2 py / H) tan(fov/2) H / W.
// In stereo (camera/stereo.hpp) W x H is one eye's picture and the eyes
// are parallel pinholes half the separation left and right of the
// observer along the camera's right.

#include <cmath>
#include <optional>
#include <string_view>
#include <tuple>

#include "camera/camera_axes.hpp"
#include "camera/pinhole_params.hpp"
#include "camera/camera_sample.hpp"
#include "camera/stereo.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/image_wrap.hpp"
#include "core/tensor.hpp"
#include "image/video_layout.hpp"

namespace lc {

class PinholeCamera {
 public:
  using Params = PinholeParams;
  static constexpr std::string_view name = Params::name;  // lc.camera{...}
  static constexpr bool rays_everywhere = true;

  // Image size in pixels; the parameters' angles are in degrees.
  PinholeCamera(const Params& p, int width, int height)
      : frame_(p.stereo, width, height),
        tan_half_(std::tan(0.5 * p.fov * degree)),
        half_separation_(p.stereo == StereoLayout::mono ? 0.0 : 0.5 * p.separation),
        width_(frame_.eye_width()),
        height_(frame_.eye_height()) {
    axes_ = turned_axes(p.yaw, p.pitch, p.roll);
  }

  // The ray through the sample's image point: every point has one, from
  // the observer's own event, or in stereo from the eye whose picture the
  // point is in.
  std::optional<CameraRay> ray(const CameraSample& s) const {
    if (frame_.layout() == StereoLayout::mono) return CameraRay{direction(s.px, s.py), {}, s.time};
    const EyePoint v = frame_.view(s.px, s.py);
    CameraRay r{direction(v.px, v.py), {}, s.time};
    for (int k = 0; k < 3; ++k) r.eye[k] = v.eye * half_separation_ * axes_.right[k];
    return r;
  }

  // Direction (on the legs, unit length) through the image point (px, py) in
  // pixel units of an eye's picture (the frame, in mono): pixel (i, j)
  // spans [i, i+1] x [j, j+1], j = 0 at the top.
  Vec3 direction(double px, double py) const {
    const Vec3& forward_ = axes_.forward;
    const Vec3& up_ = axes_.up;
    const Vec3& right_ = axes_.right;
    const double x = (2.0 * px / width_ - 1.0) * tan_half_;
    const double y = (1.0 - 2.0 * py / height_) * tan_half_ * height_ / width_;
    Vec3 d = {forward_[0] + x * right_[0] + y * up_[0], forward_[1] + x * right_[1] + y * up_[1],
              forward_[2] + x * right_[2] + y * up_[2]};
    const double n = 1.0 / norm3(d);
    return {d[0] * n, d[1] * n, d[2] * n};
  }

  ImageWrap wrap() const { return {}; }  // an image with edges
  VideoLayout video_layout() const { return {VideoProjection::flat, frame_.layout()}; }
  std::vector<EyePicture> pictures() const { return frame_.pictures(); }
  const CameraAxes& axes() const { return axes_; }

 private:
  CameraAxes axes_;
  StereoFrame frame_;
  double tan_half_, half_separation_;
  int width_, height_;  // of an eye's picture
};

}  // namespace lc
