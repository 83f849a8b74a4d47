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

// Adds `stars` (a sky's: sky_point_stars) to `image`'s colour from the
// frame's rays' sky points (`rays`: FrameImage::sky, one per pixel).
// `camera` is the frame's, for the image's size.  Runs on up to `threads`
// threads (the image the same to the bit for any number) and adds the CPU
// time it took, summed over them, to *cpu_seconds if given.  Returns the
// number of star images drawn.  Where the camera has no ray through any
// part of a pixel (outside a fisheye's disc) the pixel stays black.
long draw_point_stars(const PointStars& stars, const Camera& camera, std::span<const SkyPoint> rays,
                      FrameImage& image, int threads = 1, double* cpu_seconds = nullptr);

// One instant of a blurred frame's shutter as the star stage sees it: its
// sky's stars and its camera.
struct InstantStars {
  const PointStars* stars;
  const Camera* camera;
};

// The stars of a blurred frame (docs/motion_blur.md): each instant's drawn
// from its own plane of `rays` (FrameImage::sky: a plane per instant) and
// added with weight 1/K, so a star moving across the image leaves a streak
// of K images whose light sums to the star's.  Otherwise as
// draw_point_stars.
long draw_point_stars(std::span<const InstantStars> instants, std::span<const SkyPoint> rays, FrameImage& image,
                      int threads = 1, double* cpu_seconds = nullptr);

}  // namespace lc
