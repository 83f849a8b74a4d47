#include "stars/star_pass.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/cpu_time.hpp"
#include "core/parallel_for.hpp"
#include "stars/glare_kernel.hpp"
#include "stars/magnification.hpp"
#include "stars/pass_constants.hpp"
#include "stars/pixel_deposits.hpp"
#include "stars/pixel_light.hpp"
#include "stars/ray_grid.hpp"
#include "stars/sky_patch.hpp"
#include "stars/star_image.hpp"
#include "stars/star_search.hpp"

namespace lc {

namespace {

// Where the light of images along a path is put down: no farther apart
// than this (pixels), so the tent filter (a pixel either side) draws a
// continuous line.
constexpr double streak_spacing = 0.5;

// The images found in the row of tiles whose top quads are at j = tj
// (quads (i, j), -1 <= i < width, tj <= j < tj + star_tile): each tile's
// patches and the stars that may be in them (StarSearch), each star that is
// bright enough to be seen there and in its patch (place_in_patch) as an
// image (image_at, with the magnifications at the corners) and its light as
// the light model shows it (seen_light).  Reads no other row's results (the
// areas it needs beyond its edge are made again: the same numbers), so rows
// can run on any threads in any order.
std::vector<FoundStarImage> find_in_row_of_tiles(const RayGrid& grid, const StarField& field,
                                                 const CameraDirections& camera, const StarPassOptions& options,
                                                 double cos_max, int tj) {
  Magnifications mu(grid, camera, cos_max, options.max_magnification);
  StarSearch search(grid, field, cos_max);
  std::vector<FoundStarImage> row;
  const ImageWrap& wrap = grid.wrap();
  const PatchStars find = [&](int i, int j, const SkyPatch& patch, std::span<const std::size_t> stars) {
    // Across a wrapped seam quads -1 and width - 1 are one patch of sky:
    // the second draws it (its images land at x near width, the tent
    // filter carries them over).
    if (wrap.columns && i < 0) return;
    const double least = mu.least_luminance_drawn(i, j, invisible_share, field.faintest_luminance());
    for (const std::size_t s : stars) {
      const Vec3& d = field.stars()[s].direction;
      if (!(field.luminance(s) >= least) || !patch.may_hold(d)) continue;
      const auto uv = place_in_patch(patch, d);
      if (!uv) continue;
      const StarImage image =
          image_at(patch, *uv, {mu.at_node(i, j), mu.at_node(i + 1, j), mu.at_node(i + 1, j + 1), mu.at_node(i, j + 1)});
      row.push_back({s, image.x, image.y, image.magnification, seen_light(field, s, image)});
    }
  };
  for (int ti = -1; ti < grid.width(); ti += star_tile) search.tile(ti, tj, find);
  return row;
}

// Lands `share` of the image's light evenly along the segment from a to b
// (pixel units), in pieces no farther apart than streak_spacing; on a wrapped
// image a piece past the seam is put back across it.
void splat_along(const FoundStarImage& image, double share, const std::array<double, 2>& a,
                 const std::array<double, 2>& b, int width, int height, const ImageWrap& wrap,
                 std::vector<Deposit>& out) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::hypot(dx, dy) / streak_spacing)));
  for (int m = 0; m < pieces; ++m) {
    const double t = (m + 0.5) / pieces;
    double x = a[0] + t * dx;
    if (wrap.columns) x -= width * std::floor(x / width);
    splat_tent(x, a[1] + t * dy, image.magnification * share / pieces, image.light, width, height, wrap, out);
  }
}

// Throws std::invalid_argument for a picture too small for quads of rays.
void check_picture_size(int width, int height) {
  if (width < star_pass_min_side || height < star_pass_min_side)
    throw std::invalid_argument(fmt::format("star pass: a picture of {}x{} pixels; point stars are drawn on pictures of "
                                            "at least {}x{}",
                                            width, height, star_pass_min_side, star_pass_min_side));
}

}  // namespace

std::vector<FoundStarImage> find_star_images(std::span<const SkyPoint> sky, int width, int height,
                                             const StarField& field, const CameraDirections& camera,
                                             const StarPassOptions& options, double* cpu_seconds) {
  const int w = width, h = height;
  const std::size_t pixels = static_cast<std::size_t>(std::max(w, 0)) * static_cast<std::size_t>(std::max(h, 0));
  check_picture_size(w, h);
  if (sky.size() != pixels) throw std::invalid_argument("star pass: the frame's rays do not match its size");
  const double start = thread_cpu_seconds();
  const RayGrid grid(sky, w, h, options.wrap);
  const double cos_max = std::cos(options.max_patch_radius);
  // The rows of tiles (tj = -1, -1 + star_tile, ...) apart, their images
  // joined in row order: the one-thread pass's to the bit.
  const int tile_rows = (h + 1 + star_tile - 1) / star_tile;
  std::vector<std::vector<FoundStarImage>> rows(static_cast<std::size_t>(tile_rows));
  double cpu = 0.0;
  parallel_for(rows.size(), {.threads = options.threads, .helpers_cpu = &cpu}, [&](std::size_t r) {
    rows[r] = find_in_row_of_tiles(grid, field, camera, options, cos_max, -1 + static_cast<int>(r) * star_tile);
  });
  std::vector<FoundStarImage> images;
  for (const std::vector<FoundStarImage>& r : rows) images.insert(images.end(), r.begin(), r.end());
  if (cpu_seconds) *cpu_seconds += cpu + thread_cpu_seconds() - start;
  return images;
}

void draw_star_images(std::span<const FoundStarImage> images, std::span<const StreakPath> paths, int width,
                      int height, const StarField& field, const CameraDirections& camera,
                      const StarPassOptions& options, std::span<float> rgb, double* cpu_seconds) {
  const int w = width, h = height;
  const std::size_t pixels = static_cast<std::size_t>(std::max(w, 0)) * static_cast<std::size_t>(std::max(h, 0));
  check_picture_size(w, h);
  if (rgb.size() != 3 * pixels || !(paths.empty() || paths.size() == images.size()))
    throw std::invalid_argument("star pass: the frame's pixels or the stars' paths do not match its size");
  const double start = thread_cpu_seconds();
  double cpu = 0.0;
  std::vector<Deposit> deposits;
  deposits.reserve(4 * images.size());
  for (std::size_t k = 0; k < images.size(); ++k) {
    const FoundStarImage& image = images[k];
    const std::array<double, 2> at{image.x, image.y};
    const bool still = paths.empty() || (paths[k].before == at && paths[k].after == at);
    if (still) {
      splat_tent(image.x, image.y, image.magnification, image.light, w, h, options.wrap, deposits);
    } else {
      splat_along(image, 0.5, paths[k].before, at, w, h, options.wrap, deposits);
      splat_along(image, 0.5, at, paths[k].after, w, h, options.wrap, deposits);
    }
  }
  sum_deposits_per_pixel(deposits);
  const std::optional<GlareKernel> kernel =
      options.glare > 0.0 ? std::optional<GlareKernel>(GlareKernel(options.glare_radius)) : std::nullopt;
  const GlareSpread spread{kernel ? &*kernel : nullptr, options.glare, invisible_share, field.faintest_luminance()};
  const std::vector<LitPixel> lit = light_pixels(deposits, camera, spread, options.threads, cpu);
  add_lit_pixels(deposits, lit, spread, w, h, star_tile, options.threads, rgb, cpu);
  if (cpu_seconds) *cpu_seconds += cpu + thread_cpu_seconds() - start;
}

long add_point_stars(std::span<const SkyPoint> sky, int width, int height, const StarField& field,
                     const CameraDirections& camera, const StarPassOptions& options, std::span<float> rgb,
                     double* cpu_seconds) {
  const std::size_t pixels = static_cast<std::size_t>(std::max(width, 0)) * static_cast<std::size_t>(std::max(height, 0));
  check_picture_size(width, height);
  if (sky.size() != pixels || rgb.size() != 3 * pixels)
    throw std::invalid_argument("star pass: the frame's rays or pixels do not match its size");
  const std::vector<FoundStarImage> images = find_star_images(sky, width, height, field, camera, options, cpu_seconds);
  draw_star_images(images, {}, width, height, field, camera, options, rgb, cpu_seconds);
  return static_cast<long>(images.size());
}

}  // namespace lc
