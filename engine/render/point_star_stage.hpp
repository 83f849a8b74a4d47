#pragma once
// The star pass as a stage of the pipeline (docs/architecture.md): after
// the pixels of a frame are all in, before its files are written, the
// stars of a sky that has them as points (sky/point_star_sky.hpp) are
// drawn from the rays' sky points (stars/star_pass.hpp).  The stage needs
// only the frame's sky and camera, so the process that writes frames (the
// farm's master) runs it without the scene's spacetime or objects.

#include <span>

#include "camera/camera.hpp"
#include "image/frame_image.hpp"
#include "sky/sky.hpp"

namespace lc {

// Adds the stars of `sky` to `image`'s colour when the sky has point stars
// and the frame kept its rays' sky points (`rays`: FrameImage::sky, one per
// pixel, or none).  `camera` is the frame's, for the image's size.  Returns
// the number of star images drawn.
long draw_point_stars(const Sky& sky, const Camera& camera, std::span<const SkyPoint> rays, FrameImage& image);

}  // namespace lc
