#pragma once
// Stars as points, added to a finished frame (docs/architecture.md: the
// star pass runs after the pixels): each quad of four neighbouring pixel
// centres whose rays all reached the sky sees a patch of it (stars/
// sky_quad.hpp); a star in that patch sends the camera flux F mu, spread
// over the quad's four pixels with bilinear weights.  mu, the lensing
// magnification Omega_camera / Omega_sky, is interpolated at the star from
// the quad's corners, each pixel's 1 / (the mean patch around it): second
// order, where one patch's area alone was off by percents on a demagnified
// image.  The weights sum to 1, so a star's light is conserved as it
// moves across pixels (no flicker), and a star has as many images as
// patches that hold it, each with its own magnification.

#include <span>
#include <vector>

#include "core/color.hpp"
#include "core/tensor.hpp"
#include "stars/star_bins.hpp"

namespace lc {

struct PointStar {
  Vec3 direction;  // unit vector on the sky (the trace chart's directions at infinity)
  Color flux;      // linear RGB, per unit area facing it (what a pixel of solid angle Omega shows as flux / Omega)
};

// Where each pixel centre's ray went: its direction at infinity, or none
// (it met the disk, an object or the horizon).  Row by row, width x height.
struct SkyDirections {
  int width = 0, height = 0;
  std::vector<Vec3> direction;
  std::vector<unsigned char> reached;  // 1 where the ray reached the sky
};

struct StarPassOptions {
  double pixel_solid_angle = 0.0;  // the camera's, per pixel (sr): with max_magnification, the smallest patch
  double max_magnification = 1e4;  // mu is clamped here (caustics, where a patch shrinks to nothing)
  double max_patch_radius = 0.3;   // a patch wider (rad, centre to corner) straddles a branch of rays: skipped
};

// Adds the stars' light into `radiance` (width x height, linear RGB, row by
// row).  Pixels on the image's edge get their outer quads from directions
// extrapolated half a pixel beyond it.  Returns how many star images were
// added.
long add_point_stars(const SkyDirections& sky, std::span<const PointStar> stars, const StarBins& bins,
                     const StarPassOptions& options, std::span<Color> radiance);

}  // namespace lc
