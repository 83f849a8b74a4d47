#pragma once
// The camera of a frame (Camera): one registered kind (camera/camera_registry.hpp)
// built for the frame's image size from the spec a shot gave
// (camera/camera_spec.hpp).  A camera maps a sample (an image point and a
// time within the frame: camera/camera_sample.hpp) to the ray through it,
// if it has one: a direction in the eye's frame, the eye's place relative
// to the observer, the sample's time.  The kind is held out of sight and
// its code runs in camera/camera.cpp, so what holds a camera (a scene, the
// star stage) is not rebuilt for a new kind; a call per sample costs
// nothing beside the geodesic it starts.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera_axes.hpp"
#include "camera/camera_sample.hpp"
#include "camera/camera_spec.hpp"
#include "camera/image_window.hpp"
#include "camera/stereo.hpp"
#include "core/image_wrap.hpp"
#include "core/tensor.hpp"
#include "image/video_layout.hpp"

namespace lc {

struct CameraKinds;  // camera/camera_registry.hpp

// The camera of a frame, for its image size; or of a window of the frame
// (render --region): then the image is the window, width x height pixels
// of the whole frame's, every image point the whole frame's point it
// covers, and the window a flat picture with edges of its own.
class Camera {
 public:
  Camera(const CameraSpec& spec, int width, int height, const ImageWindow& window = {});

  std::optional<CameraRay> ray(const CameraSample& s) const;
  // The direction through image point (px, py) of an eye's picture (the
  // frame, in mono), for what works with directions alone (the star
  // stage's patches of sky, tests): where the camera has a ray, that ray's
  // direction; beyond (a fisheye's disc, a picture's edge), the camera's
  // projection continued, so patches at the edge of where it has rays
  // keep their solid angle.
  Vec3 direction(double px, double py) const;
  // Whether every image point has a ray (a pinhole's), so nothing need
  // be masked where it has none.
  bool rays_everywhere() const;
  // Where the image continues past its edges (a whole sphere's).
  ImageWrap wrap() const;
  // The eyes' pictures in the frame: the whole frame, or each eye's half.
  std::vector<EyePicture> pictures() const;
  // The whole frame's height (the image's, but for a window): what sizes
  // relative to the frame (a point-star sky's glare) are measured in.
  int frame_height() const { return window_.windowed() ? window_.frame_height : height_; }
  // How a player must show the frames (a 360-degree video's sphere; a
  // window is a check, a flat picture).
  VideoLayout video_layout() const;
  // What is odd about the image size for this camera (an equirect frame
  // whose pixels are not square), for a warning; nullopt for most.
  std::optional<std::string> size_warning() const;
  const CameraAxes& axes() const;

 private:
  std::shared_ptr<const CameraKinds> kind_;  // never null; shared by copies, never changed
  ImageWindow window_;
  int width_, height_;  // the image's: the window's, or the frame's
};

}  // namespace lc
