#pragma once
// A data layer of a frame's EXR (docs/layers.md) as a false-colour PNG, for
// the monitor's page: each value placed between the layer's smallest and
// largest finite value and coloured along viridis (blue, green, yellow;
// perceptually even: van der Walt & Smith 2015), what is not finite black.

#include <string>

#include "image/frame_image.hpp"

namespace lc::monitor {

// The layer `name` of `frame` as an 8-bit RGB picture of the frame's size
// (linear values, ready for write_png).  Returns false when the frame has
// no such layer.
bool layer_picture(const FrameImage& frame, const std::string& name, FrameImage& picture);

}  // namespace lc::monitor
