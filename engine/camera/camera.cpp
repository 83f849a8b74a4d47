#include "camera/camera.hpp"

#include <type_traits>
#include <variant>

#include "camera/camera_registry.hpp"

namespace lc {

Camera::Camera(const CameraSpec& spec, int width, int height, const ImageWindow& window)
    : kind_(std::make_shared<const CameraKinds>(
          CameraRegistry::build(spec.kinds(), window.windowed() ? window.frame_width : width,
                                window.windowed() ? window.frame_height : height))),
      window_(window),
      width_(width),
      height_(height) {}

std::optional<CameraRay> Camera::ray(const CameraSample& s) const {
  const CameraSample in_frame{s.px + window_.x0, s.py + window_.y0, s.time};
  return std::visit([&](const auto& c) { return c.ray(in_frame); }, *kind_);
}

Vec3 Camera::direction(double px, double py) const {
  return std::visit([&](const auto& c) { return c.direction(px + window_.x0, py + window_.y0); }, *kind_);
}

bool Camera::rays_everywhere() const {
  return std::visit([](const auto& c) { return std::decay_t<decltype(c)>::rays_everywhere; }, *kind_);
}

ImageWrap Camera::wrap() const {
  const ImageWrap whole = std::visit([](const auto& c) { return c.wrap(); }, *kind_);
  if (!window_.windowed()) return whole;
  // A window as wide as the frame still goes round; its rows are not
  // the poles'.
  return {whole.columns && width_ == window_.frame_width, false};
}

std::vector<EyePicture> Camera::pictures() const {
  if (window_.windowed()) return {{0, 0, 0, width_, height_}};  // windows of mono frames only (render --region)
  return std::visit([](const auto& c) { return c.pictures(); }, *kind_);
}

VideoLayout Camera::video_layout() const {
  if (window_.windowed()) return {};
  return std::visit([](const auto& c) { return c.video_layout(); }, *kind_);
}

std::optional<std::string> Camera::size_warning() const {
  return std::visit(
      [](const auto& c) -> std::optional<std::string> {
        if constexpr (requires { c.size_warning(); })
          return c.size_warning();
        else
          return std::nullopt;
      },
      *kind_);
}

const CameraAxes& Camera::axes() const {
  return std::visit([](const auto& c) -> const CameraAxes& { return c.axes(); }, *kind_);
}

}  // namespace lc
