#pragma once
// The star pass's sixth stage (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them", 5): a star image's light lands on the 2 x 2 pixels
// around its place with a tent filter, as deposits of flux (radiance times
// the pixel's solid angle); the weights sum to 1, so a star's light is kept
// as it moves across pixels (no flicker).  Then the deposits on each pixel
// are summed, a crowded lensed ring putting many on one.

#include <algorithm>
#include <vector>

#include "core/color.hpp"
#include "core/image_wrap.hpp"

namespace lc {

// Light landed on pixel (i, j) (its flux: radiance times its solid angle).
struct Deposit {
  int i, j;
  Color flux;
};

// Appends to `out` the light `flux` times `magnification` of the image at
// (x, y) (pixel units from the image's top-left corner) as it lands on the
// pixels whose centres are within one pixel of it, with the tent filter's
// weights; the share that falls outside the width x height image is lost,
// but where the image wraps: a pixel beyond the left or right edge is the
// one across the seam, beyond the top or bottom row the one half a turn
// away on that row.
void splat_tent(double x, double y, double magnification, const Color& flux, int width, int height,
                const ImageWrap& wrap, std::vector<Deposit>& out);

// Sorts `deposits` by row, then column, and sums those on one pixel into
// one, in the order they are sorted in (std::sort's: the same for the same
// input).
void sum_deposits_per_pixel(std::vector<Deposit>& deposits);

}  // namespace lc
