#pragma once
// The registry of cameras: every kind lightcone knows, one line each in
// the variant below, each a class satisfying CameraModel in its own file.
// A camera maps a sample (an image point and a time within the frame:
// camera/camera_sample.hpp) to the ray through it, if it has one: a
// direction in the eye's frame, the eye's place relative to the observer,
// the sample's time.  The scene holds the parameters a shot gave
// (CameraSpec: lc.<name>{...}), the built scene the camera for its image
// size (Camera).

#include <array>
#include <concepts>
#include <optional>
#include <string_view>
#include <type_traits>
#include <variant>

#include "camera/camera_axes.hpp"
#include "camera/camera_sample.hpp"
#include "camera/pinhole.hpp"
#include "core/fields.hpp"
#include "core/registry.hpp"

namespace lc {

// What a camera is: name (its Lua constructor lc.<name>{...}), Params with
// declared fields (orientation_fields for yaw, pitch and roll), a
// constructor from them and the image size, the ray through a sample
// (nullopt where it has none), and its axes (for reports).
template <class C>
concept CameraModel = requires(const C& c, const typename C::Params& p, const CameraSample& s) {
  requires std::same_as<std::remove_cv_t<decltype(C::name)>, std::string_view>;
  requires HasFields<typename C::Params>;
  C(p, 1, 1);
  { c.ray(s) } -> std::same_as<std::optional<CameraRay>>;
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

  std::optional<CameraRay> ray(const CameraSample& s) const {
    return std::visit([&](const auto& c) { return c.ray(s); }, kind_);
  }
  // The direction through image point (px, py) at the frame's moment, for
  // what works with directions alone (the star stage's patches of sky,
  // tests); (0, 0, 0) where the camera has no ray.
  Vec3 direction(double px, double py) const {
    const std::optional<CameraRay> r = ray({px, py, 0.0});
    return r ? r->direction : Vec3{0.0, 0.0, 0.0};
  }
  const CameraAxes& axes() const {
    return std::visit([](const auto& c) -> const CameraAxes& { return c.axes(); }, kind_);
  }

 private:
  CameraRegistry::Kinds kind_;
};

}  // namespace lc
