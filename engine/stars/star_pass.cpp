#include "stars/star_pass.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "core/cpu_time.hpp"
#include "stars/glare_kernel.hpp"
#include "stars/magnification.hpp"
#include "stars/parallel_for.hpp"
#include "stars/pass_constants.hpp"
#include "stars/pixel_deposits.hpp"
#include "stars/pixel_light.hpp"
#include "stars/ray_grid.hpp"
#include "stars/sky_patch.hpp"
#include "stars/star_image.hpp"
#include "stars/star_search.hpp"

namespace lc {

namespace {

// What one row of tiles found: its deposits in the order it made them, and
// how many star images.
struct TileRow {
  std::vector<Deposit> deposits;
  long images = 0;
};

// The stages from the patches to the deposits for the row of tiles whose
// top quads are at j = tj (quads (i, j), -1 <= i < width, tj <= j < tj +
// star_tile): each tile's patches and the stars that may be in them
// (StarSearch), each star that is bright enough to be seen there and in its
// patch (place_in_patch) as an image (image_at, with the magnifications at
// the corners), its light as the light model shows it (seen_light) landed
// on the pixels (splat_tent).  Reads no other row's results (the areas it
// needs beyond its edge are made again: the same numbers), so rows can run
// on any threads in any order.
TileRow draw_row_of_tiles(const RayGrid& grid, const StarField& field, const CameraDirections& camera,
                          const StarPassOptions& options, double cos_max, int tj) {
  Magnifications mu(grid, camera, cos_max, options.max_magnification);
  StarSearch search(grid, field, cos_max);
  TileRow row;
  const ImageWrap& wrap = grid.wrap();
  const PatchStars draw = [&](int i, int j, const SkyPatch& patch, std::span<const std::size_t> stars) {
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
      splat_tent(image.x, image.y, image.magnification, seen_light(field, s, image), grid.width(), grid.height(),
                 wrap, row.deposits);
      ++row.images;
    }
  };
  for (int ti = -1; ti < grid.width(); ti += star_tile) search.tile(ti, tj, draw);
  return row;
}

}  // namespace

long add_point_stars(std::span<const SkyPoint> sky, int width, int height, const StarField& field,
                     const CameraDirections& camera, const StarPassOptions& options, std::span<float> rgb,
                     double* cpu_seconds) {
  const int w = width, h = height;
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (w < star_pass_min_side || h < star_pass_min_side)
    throw std::invalid_argument(fmt::format("star pass: a picture of {}x{} pixels; point stars are drawn on pictures of "
                                            "at least {}x{}",
                                            w, h, star_pass_min_side, star_pass_min_side));
  if (sky.size() != pixels || rgb.size() != 3 * pixels)
    throw std::invalid_argument("star pass: the frame's rays or pixels do not match its size");
  const double start = thread_cpu_seconds();
  const RayGrid grid(sky, w, h, options.wrap);
  const double cos_max = std::cos(options.max_patch_radius);
  // The rows of tiles (tj = -1, -1 + star_tile, ...) apart, their deposits
  // joined in row order: the one-thread pass's to the bit.
  const int tile_rows = (h + 1 + star_tile - 1) / star_tile;
  std::vector<TileRow> rows(static_cast<std::size_t>(tile_rows));
  double cpu = 0.0;
  for_each_parallel(rows.size(), options.threads, [&](std::size_t r) {
    rows[r] = draw_row_of_tiles(grid, field, camera, options, cos_max, -1 + static_cast<int>(r) * star_tile);
  }, cpu);
  std::vector<Deposit> deposits;
  long images = 0;
  for (TileRow& r : rows) {
    deposits.insert(deposits.end(), r.deposits.begin(), r.deposits.end());
    images += r.images;
  }
  sum_deposits_per_pixel(deposits);
  const std::optional<GlareKernel> kernel =
      options.glare > 0.0 ? std::optional<GlareKernel>(GlareKernel(options.glare_radius)) : std::nullopt;
  const GlareSpread spread{kernel ? &*kernel : nullptr, options.glare, invisible_share, field.faintest_luminance()};
  const std::vector<LitPixel> lit = light_pixels(deposits, camera, spread, options.threads, cpu);
  add_lit_pixels(deposits, lit, spread, w, h, star_tile, options.threads, rgb, cpu);
  if (cpu_seconds) *cpu_seconds += cpu + thread_cpu_seconds() - start;
  return images;
}

}  // namespace lc
