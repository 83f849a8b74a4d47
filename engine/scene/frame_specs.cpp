#include "scene/frame_specs.hpp"

#include <fmt/format.h>

#include "camera/camera.hpp"

namespace lc {

namespace {

// "lc.camera (flat, mono)": what a player must be told of a camera's frames.
std::string kind_and_layout(const CameraSpec& spec, const VideoLayout& layout) {
  return fmt::format("lc.{} ({}, {})", kind_name(spec), name_of(layout.projection), name_of(layout.stereo));
}

}  // namespace

std::optional<CameraCut> camera_cut(const CameraSpec& at_frame, const CameraSpec& at_instant) {
  // The layout depends on the parameters alone, not the image size (a size
  // both eyes' pictures and any camera can be built at).
  const VideoLayout a = Camera(at_frame, 64, 64).video_layout(), b = Camera(at_instant, 64, 64).video_layout();
  if (at_frame.index() == at_instant.index() && a == b) return std::nullopt;
  return CameraCut{kind_and_layout(at_frame, a), kind_and_layout(at_instant, b)};
}

}  // namespace lc
