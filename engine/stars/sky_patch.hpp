#pragma once
// The star pass's second stage (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them", 2): the patch of sky between four neighbouring nodes
// of the rays' grid (stars/ray_grid.hpp) that all reached the sky, as a
// spherical quadrilateral (stars/sky_quad.hpp), with the cap that holds it
// and, where it is convex, its edges' planes: what the search for the stars
// in it (stars/star_search.hpp) and the exact test (stars/star_image.hpp)
// need.

#include <array>
#include <optional>

#include "core/tensor.hpp"
#include "stars/ray_grid.hpp"
#include "stars/sky_quad.hpp"

namespace lc {

struct SkyPatch {
  SkyQuad sky;                     // the corners' directions, in order around it
  Vec3 centre;                     // the unit mean of the corners
  double cos_reach;                // cosine of the angle from the centre to the farthest corner
  std::array<GridNode, 4> corner;  // the nodes it spans, corner k at sky.c[k]
  // The planes of its edges (great circles; edge k from corner k to k + 1),
  // normals pointing in, when the patch is convex (else `convex` is false
  // and every star in its cap may be in it).
  std::array<Vec3, 4> inward{};
  bool convex = false;

  // Whether the unit direction d may be in the patch: within its cap and on
  // the inner side of every edge's plane.  A cheap test before
  // SkyQuad::locate, generous on the edges (locate decides there).
  bool may_hold(const Vec3& d) const {
    if (!(dot3(d, centre) >= cos_reach)) return false;
    if (!convex) return true;
    for (const Vec3& n : inward)
      if (dot3(d, n) < -1e-9 * norm3(n)) return false;
    return true;
  }
};

// The patch of nodes a, b, c, d (in order around it), if all are known and
// it is no wider than cos_max says (the cosine of the largest angle from its
// centre to a corner: a wider patch straddles a jump between rays, a
// shadow's edge or a caustic).
std::optional<SkyPatch> make_patch(const GridNode& a, const GridNode& b, const GridNode& c, const GridNode& d,
                                   double cos_max);

// The patch of grid quad (i, j): nodes (i, j), (i + 1, j), (i + 1, j + 1),
// (i, j + 1), -1 <= i < width, -1 <= j < height.
inline std::optional<SkyPatch> patch_of(const RayGrid& grid, int i, int j, double cos_max) {
  return make_patch(grid.at(i, j), grid.at(i + 1, j), grid.at(i + 1, j + 1), grid.at(i, j + 1), cos_max);
}

}  // namespace lc
