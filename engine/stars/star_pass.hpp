#pragma once
// Stars as points, added to a finished frame (docs/stars.md; the pipeline's
// stage after the pixels).  The pass is a chain of stages, each in its own
// file, in the order the data flows:
//  1. stars/ray_grid.hpp: the frame's rays (one per pixel, at a known point
//     of it: core/sky_point.hpp) as a grid of nodes, extrapolated one pixel
//     beyond the image's edge;
//  2. stars/sky_patch.hpp: each quad of four neighbouring nodes that all
//     reached the sky sees a patch of it (stars/sky_quad.hpp);
//  3. stars/magnification.hpp: mu = Omega_camera / Omega_sky at each node,
//     from the solid angles of the quads around it (second order, where one
//     quad's ratio alone was off by percents on a demagnified image);
//  4. stars/star_search.hpp: which stars may be in each patch, a tile of
//     quads at a time;
//  5. stars/star_image.hpp: a star in a patch has an image there: its place
//     is the patch's bilinear map of the star back onto the quad's four image
//     points, its mu and the light model's ratios interpolated there, its
//     light seen through them;
//  6. stars/pixel_deposits.hpp: the image's light F mu spread over the 2 x 2
//     pixels nearest its place with a tent filter (weights summing to 1, so
//     a star's light is conserved as it moves across pixels: no flicker),
//     summed per pixel;
//  7. stars/pixel_light.hpp: each lit pixel's radiance and its glare's halo
//     (stars/glare_kernel.hpp) added to the image.
// A star has as many images as patches that hold it, each with its own
// magnification.  Only pixels the camera saw sky through get stars: a star
// behind the disk's edge in a quad that touches the disk is not drawn.

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "core/color.hpp"
#include "core/image_wrap.hpp"
#include "core/sky_point.hpp"
#include "core/tensor.hpp"
#include "stars/camera_directions.hpp"
#include "stars/star_field.hpp"

namespace lc {

struct StarPassOptions {
  double max_magnification = 1e4;  // mu is clamped here (caustics, where a patch shrinks to nothing)
  double max_patch_radius = 0.3;   // a patch wider (rad, centre to corner) straddles a branch of rays: skipped
  // Glare: this fraction of each star's light is spread into a halo
  // (1 + r^2 / a^2)^-2 of scale a = glare_radius pixels, cut at 8 a.
  double glare = 0.0;
  double glare_radius = 1.0;
  // Threads the pass may use (this one among them).  The image is the
  // same to the bit for any number: rows of tiles and bands of pixels are
  // worked out apart and joined in a fixed order.
  int threads = 1;
  // Where the image continues past its edges (the camera's; an
  // equirectangular whole sphere): there the grid's ring is the rays
  // across the edge (or the pole), each seam's quads are searched once and
  // a star's light near an edge lands on the pixels across it.
  ImageWrap wrap{};
};

// The smallest picture the pass draws on, in each direction: a quad of
// rays needs two rows and two columns of them.  The render refuses a
// smaller frame, eye's picture or --region of a point-star sky before it
// starts (pipeline/cli/render_command.cpp).
inline constexpr int star_pass_min_side = 2;

// A star image as stages 1-5 find it: the star (its index in the field),
// its place (pixel units from the image's top-left corner), its
// magnification and its light as the light model shows it there, before
// the magnification.
struct FoundStarImage {
  std::size_t star;
  double x, y, magnification;
  Color light;
};

// Where a star image's light goes in a blurred frame (stars/star_streaks.hpp):
// half of it spread evenly along the straight path from `before` to the
// image's place, half from there to `after` (pixel units), the star's path
// during its instant's share of the shutter.  Both ends at the image's place:
// a point, drawn as the unblurred pass draws it.
struct StreakPath {
  std::array<double, 2> before, after;
};

// Stages 1-5: every star image of the frame whose rays are `sky` (width x
// height), in a fixed order (rows of tiles top to bottom, as one thread
// finds them).  Adds the CPU time taken, summed over the threads, to
// *cpu_seconds if given.  Throws std::invalid_argument when the frame is
// smaller than star_pass_min_side or `sky` does not match its size.
std::vector<FoundStarImage> find_star_images(std::span<const SkyPoint> sky, int width, int height,
                                             const StarField& field, const CameraDirections& camera,
                                             const StarPassOptions& options, double* cpu_seconds = nullptr);

// Stages 6-7: the light of `images` landed on the pixels and added to `rgb`
// (3 floats per pixel, width x height), each image at its place, or along
// its path where `paths` (one per image, or empty) gives one.
void draw_star_images(std::span<const FoundStarImage> images, std::span<const StreakPath> paths, int width,
                      int height, const StarField& field, const CameraDirections& camera,
                      const StarPassOptions& options, std::span<float> rgb, double* cpu_seconds = nullptr);

// Adds the stars' light to `rgb` (linear RGB, 3 floats per pixel, row by
// row, width x height); `sky` holds each pixel's ray (width x height).
// Throws std::invalid_argument where the picture is smaller than
// star_pass_min_side or `sky` and `rgb` do not match its size.
// Pixels on the image's edge get their outer quads from rays extrapolated
// one pixel beyond it, or where the image wraps from the rays across it.  Returns how many star images were added; adds the
// CPU time the pass took, summed over its threads, to *cpu_seconds if
// given.  `camera` is called from several threads at once when
// options.threads > 1.
long add_point_stars(std::span<const SkyPoint> sky, int width, int height, const StarField& field,
                     const CameraDirections& camera, const StarPassOptions& options, std::span<float> rgb,
                     double* cpu_seconds = nullptr);

}  // namespace lc
