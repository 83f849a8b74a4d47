#pragma once
// The pinhole camera of DESIGN.md in an observer's tetrad.  Directions are
// components on the tetrad's spatial legs (1, 2, 3); the default view looks
// "at the hole": forward = -e_1, up = -e_2, right = e_3.

#include <cmath>

#include "core/constants.hpp"
#include "core/tensor.hpp"
#include "scene/frame_scene.hpp"

namespace lc {

class PinholeCamera {
 public:
  // Image size in pixels; the spec's angles are in degrees.
  PinholeCamera(const CameraSpec& spec, int width, int height);

  // Direction (on the legs, unit length) through the image point (px, py) in
  // pixel units: pixel (i, j) spans [i, i+1] x [j, j+1], j = 0 at the top.
  Vec3 direction(double px, double py) const {
    const double x = (2.0 * px / width_ - 1.0) * tan_half_;
    const double y = (1.0 - 2.0 * py / height_) * tan_half_ * height_ / width_;
    Vec3 d = {forward_[0] + x * right_[0] + y * up_[0], forward_[1] + x * right_[1] + y * up_[1],
              forward_[2] + x * right_[2] + y * up_[2]};
    const double n = 1.0 / norm3(d);
    return {d[0] * n, d[1] * n, d[2] * n};
  }

  const Vec3& forward() const { return forward_; }
  const Vec3& up() const { return up_; }
  const Vec3& right() const { return right_; }

 private:
  Vec3 forward_, up_, right_;
  double tan_half_;
  int width_, height_;
};

inline PinholeCamera::PinholeCamera(const CameraSpec& spec, int width, int height)
    : tan_half_(std::tan(0.5 * spec.fov * degree)), width_(width), height_(height) {
  Vec3 f = {-1, 0, 0}, u = {0, -1, 0}, r = {0, 0, 1};
  auto turn = [](Vec3& a, Vec3& b, double angle_deg) {  // a towards b
    const double c = std::cos(angle_deg * degree), s = std::sin(angle_deg * degree);
    const Vec3 a2 = {c * a[0] + s * b[0], c * a[1] + s * b[1], c * a[2] + s * b[2]};
    const Vec3 b2 = {c * b[0] - s * a[0], c * b[1] - s * a[1], c * b[2] - s * a[2]};
    a = a2;
    b = b2;
  };
  turn(f, r, spec.yaw);
  turn(f, u, spec.pitch);
  turn(u, r, spec.roll);
  forward_ = f;
  up_ = u;
  right_ = r;
}

}  // namespace lc
