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
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "camera/camera_axes.hpp"
#include "camera/camera_sample.hpp"
#include "camera/camera_spec.hpp"
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
static_assert(std::is_same_v<CameraRegistry::Spec, CameraSpec>,
              "camera/camera_spec.hpp must list the registered cameras' Params in the registry's order");

// The camera of a frame, for its image size; or of a window of the frame
// (render --region): then the image is the window, width x height pixels
// of the whole frame's, every image point the whole frame's point it
// covers, and the window a flat picture with edges of its own.
class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height, const ImageWindow& window = {})
      : kind_(CameraRegistry::build(spec, window.windowed() ? window.frame_width : width,
                                    window.windowed() ? window.frame_height : height)),
        window_(window),
        width_(width),
        height_(height) {}

  std::optional<CameraRay> ray(const CameraSample& s) const {
    const CameraSample in_frame{s.px + window_.x0, s.py + window_.y0, s.time};
    return std::visit([&](const auto& c) { return c.ray(in_frame); }, kind_);
  }
  // The direction through image point (px, py) of an eye's picture (the
  // frame, in mono), for what works with directions alone (the star
  // stage's patches of sky, tests): where the camera has a ray, that ray's
  // direction; beyond (a fisheye's disc, a picture's edge), the camera's
  // projection continued, so patches at the edge of where it has rays
  // keep their solid angle.
  Vec3 direction(double px, double py) const {
    return std::visit([&](const auto& c) { return c.direction(px + window_.x0, py + window_.y0); }, kind_);
  }
  // Whether every image point has a ray (a pinhole's), so nothing need
  // be masked where it has none.
  bool rays_everywhere() const {
    return std::visit([](const auto& c) { return std::decay_t<decltype(c)>::rays_everywhere; }, kind_);
  }
  // Where the image continues past its edges (a whole sphere's).
  ImageWrap wrap() const {
    const ImageWrap whole = std::visit([](const auto& c) { return c.wrap(); }, kind_);
    if (!window_.windowed()) return whole;
    // A window as wide as the frame still goes round; its rows are not
    // the poles'.
    return {whole.columns && width_ == window_.frame_width, false};
  }
  // The eyes' pictures in the frame: the whole frame, or each eye's half.
  std::vector<EyePicture> pictures() const {
    if (window_.windowed()) return {{0, 0, 0, width_, height_}};  // windows of mono frames only (render --region)
    return std::visit([](const auto& c) { return c.pictures(); }, kind_);
  }
  // The whole frame's height (the image's, but for a window): what sizes
  // relative to the frame (a point-star sky's glare) are measured in.
  int frame_height() const { return window_.windowed() ? window_.frame_height : height_; }
  // How a player must show the frames (a 360-degree video's sphere; a
  // window is a check, a flat picture).
  VideoLayout video_layout() const {
    if (window_.windowed()) return {};
    return std::visit([](const auto& c) { return c.video_layout(); }, kind_);
  }
  // What is odd about the image size for this camera (an equirect frame
  // whose pixels are not square), for a warning; nullopt for most.
  std::optional<std::string> size_warning() const {
    return std::visit(
        [](const auto& c) -> std::optional<std::string> {
          if constexpr (requires { c.size_warning(); })
            return c.size_warning();
          else
            return std::nullopt;
        },
        kind_);
  }
  const CameraAxes& axes() const {
    return std::visit([](const auto& c) -> const CameraAxes& { return c.axes(); }, kind_);
  }

 private:
  CameraRegistry::Kinds kind_;
  ImageWindow window_;
  int width_, height_;  // the image's: the window's, or the frame's
};

}  // namespace lc
