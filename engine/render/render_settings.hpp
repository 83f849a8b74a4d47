#pragma once
// What a frame is rendered with, what rendering it cost and the empty
// frame it is rendered into: what the farm passes around without the scene.  Apart from
// render/renderer.hpp so that the farm's queue, budget and messages build
// without the registries (docs/architecture.md, "What a new kind rebuilds").

#include "camera/image_window.hpp"
#include "image/frame_image.hpp"

namespace lc {

struct RenderSettings {
  int width = 0, height = 0;  // the image's: the frame's, or its window's
  int supersample = 1;  // N: N x N samples per pixel
  bool layers = false;  // also fill the data layers (render/layers.hpp)
  // N >= 2: trace one corner sample of each pixel first (alternating
  // top-left and bottom-right along the row) and the rest of its N x N grid
  // only if it disagrees with a row neighbour's (another hit kind, or a
  // colour more than adaptive_sample_threshold apart in sRGB).
  bool adaptive = true;
  // The window of the frame rendered (render --region), if any (last, so
  // the settings' aggregate initialisations stay as they were).
  ImageWindow window{};
};

struct RenderStats {
  long rays = 0, steps = 0, gave_up = 0;  // rays traced
  long reused = 0;                        // samples taken from a SampleMemo instead
  double seconds = 0.0;                   // CPU time spent on them (core-seconds), where measured
  RenderStats& operator+=(const RenderStats& o) {
    rays += o.rays;
    steps += o.steps;
    gave_up += o.gave_up;
    reused += o.reused;
    seconds += o.seconds;
    return *this;
  }
};

// An empty frame of the right size (and layers, if asked for); defined in
// render/renderer.cpp.
FrameImage make_frame(const RenderSettings& rs);

}  // namespace lc
