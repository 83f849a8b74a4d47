#pragma once
// A 4x2 frame with one lit value: what the frame store's tests write.

#include "render/renderer.hpp"

namespace lc::test {

inline FrameImage tiny_frame() {
  RenderSettings rs;
  rs.width = 4;
  rs.height = 2;
  FrameImage img = make_frame(rs);
  img.rgb[0] = 0.5f;
  return img;
}

}  // namespace lc::test
