#pragma once
// The registry of cameras: every kind lightcone knows, one line each in
// the variant below, each a class satisfying CameraModel in its own file.
// Only what builds cameras (camera/camera.cpp), documents them and tests
// them includes it; the rest holds a Camera (camera/camera.hpp).
// A camera maps a sample (an image point and a time within the frame:
// camera/camera_sample.hpp) to the ray through it, if it has one: a
// direction in the eye's frame, the eye's place relative to the observer,
// the sample's time.  The scene holds the parameters a shot gave
// (CameraSpec: lc.<name>{...}), the built scene the camera for its image
// size (Camera).

#include <array>
#include <concepts>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "camera/camera_axes.hpp"
#include "camera/camera_sample.hpp"
#include "camera/camera_params.hpp"
#include "camera/equirect.hpp"
#include "camera/fisheye.hpp"
#include "camera/image_window.hpp"
#include "camera/pinhole.hpp"
#include "camera/stereo.hpp"
#include "core/fields.hpp"
#include "core/image_wrap.hpp"
#include "core/registry.hpp"
#include "image/video_layout.hpp"

namespace lc {

// What a camera is: name (its Lua constructor lc.<name>{...}), Params with
// declared fields (orientation_fields for yaw, pitch and roll), a
// constructor from them and the image size, the ray through a sample
// (nullopt where it has none), the direction through any image point
// (its projection, continued where it has no ray: the star stage), whether
// every image point has a ray (rays_everywhere), where its image continues
// past its edges (wrap), how a player must show its frames (video_layout),
// its eyes' pictures in the frame (one; two in stereo) and its axes (for
// reports).  direction() and wrap() are an eye's picture's: both eyes of
// a stereo camera share the projection, from different places.  A camera may also
// have size_warning(): what is odd about the image size it was built for.
template <class C>
concept CameraModel = requires(const C& c, const typename C::Params& p, const CameraSample& s) {
  requires std::same_as<std::remove_cv_t<decltype(C::name)>, std::string_view>;
  requires HasFields<typename C::Params>;
  C(p, 1, 1);
  { c.ray(s) } -> std::same_as<std::optional<CameraRay>>;
  { c.direction(s.px, s.py) } -> std::same_as<Vec3>;
  { C::rays_everywhere } -> std::convertible_to<bool>;
  { c.wrap() } -> std::same_as<ImageWrap>;
  { c.video_layout() } -> std::same_as<VideoLayout>;
  { c.pictures() } -> std::same_as<std::vector<EyePicture>>;
  { c.axes() } -> std::same_as<const CameraAxes&>;
};

// Every camera kind, one line each.
using CameraRegistry = Registry<PinholeCamera, FisheyeCamera, EquirectCamera>;

// One assertion per camera: the compiler's notes name the one that fails
// and the requirement it misses.
static_assert(every_kind<CameraRegistry>([]<class C>() {
  static_assert(CameraModel<C>, "a registered camera must satisfy CameraModel");
}));

// The camera a shot asked for (camera/camera_spec.hpp): the kinds'
// parameters, listed apart in the same order.
static_assert(std::is_same_v<CameraRegistry::Spec, CameraSpecs::Spec>,
              "camera/camera_params.hpp must list the registered cameras' Params in the registry's order");

// The built camera of some kind, as a class so that camera/camera.hpp can
// name it before the registry.
struct CameraKinds : CameraRegistry::Kinds {
  using CameraRegistry::Kinds::Kinds;
  CameraKinds(CameraRegistry::Kinds&& kind) : CameraRegistry::Kinds(std::move(kind)) {}
};

}  // namespace lc
