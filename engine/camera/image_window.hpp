#pragma once
// A window of a frame (render --region, docs/cli.md): the rectangle of the
// whole frame's pixels [x0, x0 + width) x [y0, y0 + height) rendered as an
// image of its own, every pixel as it is in the whole frame, for checking
// part of a large frame (an 8K dome master) without rendering all of it.

namespace lc {

struct ImageWindow {
  int x0 = 0, y0 = 0;                    // the window's top-left pixel in the whole frame
  int frame_width = 0, frame_height = 0;  // the whole frame's size; 0: no window (the image is the frame)
  bool windowed() const { return frame_width > 0; }
  bool operator==(const ImageWindow&) const = default;
};

}  // namespace lc
