#pragma once
// One rendered frame as plain data: linear RGB plus named per-pixel float
// layers.  The renderer fills it, the frame store writes it (image_io.hpp).

#include <algorithm>
#include <string>
#include <vector>

#include "core/sky_point.hpp"

namespace lc {

// Largest image side the image layer reads, writes or generates.  Anything
// bigger is taken as a corrupt header or a mistake (a 32768 x 16384 float
// sky is already 6 GiB in memory), not as a picture worth allocating for.
inline constexpr int max_image_side = 32768;

// Linear RGB (3 floats per pixel, row-major, row 0 at the top) plus
// optional named data layers (e.g. "hit.kind", "hit.r"), width * height
// floats each, same pixel order.
struct FrameImage {
  int width = 0, height = 0;
  std::vector<float> rgb;  // 3 * width * height
  struct Layer {
    std::string name;
    std::vector<float> values;  // width * height
  };
  std::vector<Layer> layers;
  // Each pixel's ray where the frame's sky has stars drawn as points (the
  // star pass reads them; render/renderer.hpp's prepare_frame makes room),
  // else empty; a plane of width * height of them per instant of a blurred
  // frame's shutter (docs/motion_blur.md).  Not written to the frame's files.
  std::vector<SkyPoint> sky;
  // Per pixel, the share of its samples the camera had a ray for (0 outside
  // a dome master's disc), where make_frame made room for it; empty: every
  // pixel opaque.  The frame's files carry it only where some pixel is not
  // (image_io).
  std::vector<float> alpha;

  // Planes of sky points held: 0, 1, or one per instant of the shutter.
  std::size_t sky_planes() const {
    const std::size_t n = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    return n == 0 ? 0 : sky.size() / n;
  }
};

// Whether some pixel of `image` is not opaque: the frame's EXR then has an
// A channel (image_io.hpp).  A frame every pixel of which had a ray (a
// pinhole's) has none, so its files are what they were before alpha.
inline bool has_transparency(const FrameImage& image) {
  return std::any_of(image.alpha.begin(), image.alpha.end(), [](float a) { return a != 1.0f; });
}

}  // namespace lc
