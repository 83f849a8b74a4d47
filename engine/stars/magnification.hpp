#pragma once
// The star pass's third stage (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them", 4): the magnification mu = Omega_camera / Omega_sky on
// the rays' grid.  Each quad of the grid has the camera's solid angle of its
// image points and the sky's of its patch (stars/sky_patch.hpp); at a node,
// mu is the ratio of the sums over the quads around it (second order: one
// quad's own ratio was off by percents on a demagnified image whose mu
// changes quickly across it).  The areas are made once each and kept: the
// quads around one star's image are those around its neighbours' in a
// crowded lensed ring.

#include <cstddef>
#include <unordered_map>

#include "stars/camera_directions.hpp"
#include "stars/ray_grid.hpp"

namespace lc {

// The camera's and the sky's solid angles (sr) of a quad of the grid, 0 and
// 0 where it has no patch (a corner did not reach the sky, or the patch is
// too wide).
struct PatchAreas {
  double camera = 0.0, sky = 0.0;
};

class Magnifications {
 public:
  // grid and camera: the frame's, kept by reference; cos_max: the widest
  // patch (stars/sky_patch.hpp's make_patch); mu is clamped at
  // max_magnification where a patch shrinks to nothing (a caustic).
  // One thread's: its kept areas are not shared.
  Magnifications(const RayGrid& grid, const CameraDirections& camera, double cos_max, double max_magnification)
      : grid_(grid), camera_(camera), cos_max_(cos_max), max_magnification_(max_magnification) {}

  // Quad (i, j)'s areas, -1 <= i < width, -1 <= j < height.
  PatchAreas areas(int i, int j);

  // mu at node (i, j), -1 <= i <= width, -1 <= j <= height: the camera's
  // over the sky's solid angle of the quads around it (of those in the
  // grid; where it wraps, across the seam too), at most max_magnification; 0 where none of them has a patch.
  double at_node(int i, int j);

  // The least luminance a star's light may have for its image in quad
  // (i, j) to be drawn: `invisible` times the faintest star's (`faintest`)
  // over the most the image's magnification can be there, twice the quad's
  // own (the thin rings of images at a shadow's edge hold most of a sky's
  // stars, ever fainter).  Only for a quad that has a patch.
  double least_luminance_drawn(int i, int j, double invisible, double faintest);

 private:
  const RayGrid& grid_;
  const CameraDirections& camera_;
  double cos_max_, max_magnification_;
  std::unordered_map<std::size_t, PatchAreas> areas_;  // by (j + 1) (width + 1) + i + 1
};

}  // namespace lc
