#pragma once
// The star pass's fourth stage (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them", 3): which stars may lie in each patch of sky
// (stars/sky_patch.hpp).  The quads of the rays' grid are searched in tiles
// of star_tile x star_tile (stars/pass_constants.hpp), one lookup in the
// star bins per tile:
// - a tile that sees a small, smooth piece of sky (the usual) finds the
//   stars in the cap its nodes span, and in the plane tangent to that cap
//   (gnomonic) each quad's box of corners picks the few of them worth
//   testing;
// - a tile across a jump of the rays (a shadow's edge, where the lens
//   spreads neighbouring rays over the sky) is searched in blocks of quads,
//   each asking the bins (or its enclosing block's stars) for the cap its
//   patches span and splitting in four where that holds many stars; a patch
//   wider than a bin asks the bins alone.
// A star offered for a patch may still lie outside it (the exact test is
// SkyPatch::may_hold and place_in_patch, stars/star_image.hpp); every star
// inside is offered, once per patch.

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "stars/ray_grid.hpp"
#include "stars/sky_patch.hpp"
#include "stars/star_field.hpp"

namespace lc {

// What a search reports: quad (i, j)'s patch and the stars (indices into
// the field) that may be in it.
using PatchStars = std::function<void(int i, int j, const SkyPatch& patch, std::span<const std::size_t> stars)>;

class StarSearch {
 public:
  // grid and field: the frame's, kept by reference; cos_max: the widest
  // patch (make_patch).  One thread's: it keeps its working buffers.
  StarSearch(const RayGrid& grid, const StarField& field, double cos_max);

  // Reports, for each quad (i, j) of the tile with top-left quad (ti, tj)
  // (i in [ti, ti + star_tile) and j in [tj, tj + star_tile), both cut at
  // the grid's end: i < width, j < height) that has a patch and may hold
  // stars, the patch and those stars, in a fixed order (rows of quads, or
  // blocks of them for a tile across a jump).
  void tile(int ti, int tj, const PatchStars& report);

 private:
  // The tile's nodes (ti .. i1, tj .. j1 inclusive), made from the rays.
  void make_nodes(int ti, int tj, int i1, int j1);
  const GridNode& node(int i, int j) const;
  // The tile of quads [ti, i1) x [tj, j1) in the plane tangent to the cap
  // (unit centre, cosine of its radius `least`) that holds its nodes.
  void search_in_plane(int ti, int tj, int i1, int j1, const Vec3& centre, double least, const PatchStars& report);
  // The tile of quads [ti, i1) x [tj, j1) across a jump: wide patches alone,
  // the others in blocks.
  void search_across_jump(int ti, int tj, int i1, int j1, const PatchStars& report);
  // The block [i0, i1) x [j0, j1) of the tile at (ti, tj): the stars in the
  // cap its patches span, from `from` (the enclosing block's) or, when null,
  // the bins; split in four where they are many.
  void search_block(int ti, int tj, int i0, int j0, int i1, int j1, const std::vector<std::size_t>* from,
                    const PatchStars& report);

  const RayGrid& grid_;
  const StarField& field_;
  double cos_max_, cos_wide_, cos_plane_;
  int nodes_origin_i_ = 0, nodes_origin_j_ = 0, nodes_width_ = 0;
  std::vector<GridNode> nodes_;
  std::vector<std::optional<SkyPatch>> patches_;  // the tile's, star_tile x star_tile (across a jump)
  // A star found in a tile's tangent plane, at (x, y) there.
  struct Placed {
    double x, y;
    std::size_t star;
  };
  // Working buffers, kept from tile to tile: the stars in a tile's cap, its
  // nodes in the tangent plane, the stars by their x there, one patch's.
  std::vector<std::size_t> found_;
  std::vector<std::array<double, 2>> flat_;
  std::vector<Placed> placed_;
  std::vector<std::size_t> here_;
};

}  // namespace lc
