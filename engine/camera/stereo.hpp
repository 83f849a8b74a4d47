#pragma once
// Stereo frames (docs/cameras.md, "Stereo"): both eyes' pictures in one
// frame, the left eye's above the right's (top-bottom) or left of it
// (side-by-side), each the camera's own projection at the eye picture's
// size.  Where each eye is comes from the camera: parallel pinholes half
// the separation either side of the observer along the camera's right;
// omnidirectional stereo for the equirect (camera/equirect.hpp).  The eye's
// ray starts from the displaced event (render/ray_start.hpp).

#include <optional>
#include <tuple>
#include <vector>

#include "core/fields.hpp"
#include "image/video_layout.hpp"

namespace lc {

// Which eye an image point belongs to: -1 the left, +1 the right, 0 the
// one eye of a mono frame; and the point within that eye's picture.
struct EyePoint {
  int eye = 0;
  double px = 0.0, py = 0.0;
};

// One eye's picture in the frame: its pixels x0 .. x0 + width - 1 and
// y0 .. y0 + height - 1 (the star stage draws each picture's stars apart).
struct EyePicture {
  int eye = 0;
  int x0 = 0, y0 = 0, width = 0, height = 0;
};

class StereoFrame {
 public:
  // A width x height frame in `layout`: each eye's picture is half of it
  // (of an odd height or width, the last row or column lies past the right
  // eye's picture, where its projection continues).
  StereoFrame(StereoLayout layout, int width, int height)
      : layout_(layout),
        eye_width_(layout == StereoLayout::side_by_side ? width / 2 : width),
        eye_height_(layout == StereoLayout::top_bottom ? height / 2 : height) {}

  StereoLayout layout() const { return layout_; }
  // The size of one eye's picture.
  int eye_width() const { return eye_width_; }
  int eye_height() const { return eye_height_; }

  // The eye image point (px, py) of the frame belongs to, and where it is
  // in that eye's picture.  Past the frame's edges each eye's projection
  // continues (the star stage's patches at the edges).
  EyePoint view(double px, double py) const {
    switch (layout_) {
      case StereoLayout::mono: return {0, px, py};
      case StereoLayout::top_bottom: return py < eye_height_ ? EyePoint{-1, px, py} : EyePoint{1, px, py - eye_height_};
      case StereoLayout::side_by_side: return px < eye_width_ ? EyePoint{-1, px, py} : EyePoint{1, px - eye_width_, py};
    }
    return {0, px, py};
  }

  // The eyes' pictures: one for a mono frame, two for a stereo one.
  std::vector<EyePicture> pictures() const {
    switch (layout_) {
      case StereoLayout::mono: return {{0, 0, 0, eye_width_, eye_height_}};
      case StereoLayout::top_bottom: return {{-1, 0, 0, eye_width_, eye_height_}, {1, 0, eye_height_, eye_width_, eye_height_}};
      case StereoLayout::side_by_side: return {{-1, 0, 0, eye_width_, eye_height_}, {1, eye_width_, 0, eye_width_, eye_height_}};
    }
    return {};
  }

 private:
  StereoLayout layout_;
  int eye_width_, eye_height_;
};

// The declared fields of a camera that makes stereo frames, for a Params
// with members `stereo` (StereoLayout) and `separation` (M): a camera's
// fields are std::tuple_cat of its own, these and orientation_fields.
template <class P>
constexpr auto separation_field() {
  return field("separation", &P::separation, std::optional<double>{1.0}, above(0.0), std::nullopt,
               "stereo: the distance between the eyes, in the observer's frame", "M");
}
template <class P>
constexpr auto stereo_fields() {
  return std::tuple{
      field("stereo", &P::stereo, std::optional<StereoLayout>{StereoLayout::mono}, std::nullopt, std::nullopt,
            "both eyes in one frame: mono (one eye), top-bottom (the left eye's picture above the right's) or "
            "side-by-side (left, right)"),
      separation_field<P>(),
  };
}

}  // namespace lc
