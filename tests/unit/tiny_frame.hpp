#pragma once
// Small frames for the pipeline's tests: settings of a size, and a 4x2
// frame with one lit value (what the frame store's tests write).

#include "render/renderer.hpp"

namespace lc::test {

// Render settings of a w x h frame, the rest their defaults.
inline RenderSettings settings_of_size(int w, int h) {
  RenderSettings rs;
  rs.width = w;
  rs.height = h;
  return rs;
}

inline FrameImage tiny_frame() {
  FrameImage img = make_frame(settings_of_size(4, 2));
  img.rgb[0] = 0.5f;
  return img;
}

}  // namespace lc::test
