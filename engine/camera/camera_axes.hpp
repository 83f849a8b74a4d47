#pragma once
// A camera's orientation in the observer's frame: its forward, up and right
// axes as components on the tetrad's spatial legs (1, 2, 3).

#include <optional>
#include <string_view>
#include <tuple>

#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/tensor.hpp"

namespace lc {

struct CameraAxes {
  Vec3 forward, up, right;
};

// The default view "at the hole" (forward = -e_1, up = -e_2, right = e_3)
// turned by yaw (forward towards right), then pitch (forward towards up),
// then roll (up towards right), in degrees.
inline CameraAxes turned_axes(double yaw, double pitch, double roll) {
  Vec3 f = {-1, 0, 0}, u = {0, -1, 0}, r = {0, 0, 1};
  auto turn = [](Vec3& a, Vec3& b, double angle_deg) {  // a towards b
    const double c = std::cos(angle_deg * degree), s = std::sin(angle_deg * degree);
    const Vec3 a2 = {c * a[0] + s * b[0], c * a[1] + s * b[1], c * a[2] + s * b[2]};
    const Vec3 b2 = {c * b[0] - s * a[0], c * b[1] - s * a[1], c * b[2] - s * a[2]};
    a = a2;
    b = b2;
  };
  turn(f, r, yaw);
  turn(f, u, pitch);
  turn(u, r, roll);
  return {f, u, r};
}

// The declared fields every camera turns its view with (yaw, pitch, roll
// in degrees, in turned_axes' order), for a Params with members of those
// names: a camera's fields are std::tuple_cat of its own and these.
template <class P>
constexpr auto orientation_fields() {
  return std::tuple{
      field("yaw", &P::yaw, std::optional<double>{0.0}, std::nullopt, std::nullopt, "turns forward towards right",
            "degrees"),
      field("pitch", &P::pitch, std::optional<double>{0.0}, std::nullopt, std::nullopt, "then forward towards up",
            "degrees"),
      field("roll", &P::roll, std::optional<double>{0.0}, std::nullopt, std::nullopt, "then up towards right",
            "degrees"),
  };
}

}  // namespace lc
