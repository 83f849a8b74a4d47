#pragma once
// The registry of cameras: every kind lightcone knows, one line each in
// the variant below, each a class satisfying CameraModel in its own file.
// A camera maps an image point to a direction in the observer's frame; the
// scene holds the parameters a shot gave (CameraSpec: lc.<name>{...}), the
// built scene the camera for its image size (Camera).

#include <array>
#include <concepts>
#include <string_view>
#include <type_traits>
#include <variant>

#include "camera/camera_axes.hpp"
#include "camera/pinhole.hpp"
#include "core/fields.hpp"
#include "core/registry.hpp"

namespace lc {

// What a camera is: name (its Lua constructor lc.<name>{...}), Params with
// declared fields, a constructor from them and the image size, the
// direction (unit, on the tetrad's legs) through image point (px, py) in
// pixel units, and its axes (for reports).
template <class C>
concept CameraModel = requires(const C& c, const typename C::Params& p, double px) {
  requires std::same_as<std::remove_cv_t<decltype(C::name)>, std::string_view>;
  requires HasFields<typename C::Params>;
  C(p, 1, 1);
  { c.direction(px, px) } -> std::same_as<Vec3>;
  { c.axes() } -> std::same_as<const CameraAxes&>;
};

// Every camera kind, one line each.
using CameraRegistry = Registry<PinholeCamera>;

// One assertion per camera: the compiler's notes name the one that fails
// and the requirement it misses.
static_assert(every_kind<CameraRegistry>([]<class C>() {
  static_assert(CameraModel<C>, "a registered camera must satisfy CameraModel");
}));

// The camera a shot asked for: one of the registered kinds' parameters.
using CameraSpec = CameraRegistry::Spec;

// The camera of a frame, for its image size.
class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height) : kind_(CameraRegistry::build(spec, width, height)) {}

  Vec3 direction(double px, double py) const {
    return std::visit([&](const auto& c) { return c.direction(px, py); }, kind_);
  }
  const CameraAxes& axes() const {
    return std::visit([](const auto& c) -> const CameraAxes& { return c.axes(); }, kind_);
  }

 private:
  CameraRegistry::Kinds kind_;
};

}  // namespace lc
