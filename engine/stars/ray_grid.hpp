#pragma once
// The star pass's first stage (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them", 1): a frame's rays as a grid of nodes, one per pixel,
// each where its ray went on the sky, the image point it went through and
// how the light model sees the sky's light there; and a ring of nodes one
// pixel beyond the image's edge, extrapolated, so that the pixels on the
// edge have quads of rays on every side.  Where the image wraps
// (core/image_wrap.hpp) the ring is not made up: across the left and right
// edges it is the other edge's rays, and above the top row (below the
// bottom one) the pole itself, where the row's rays converge.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "core/image_wrap.hpp"
#include "core/sky_point.hpp"
#include "core/tensor.hpp"

namespace lc {

// A point of the grid: its ray's unit direction on the sky, the image point
// it went through (pixel units from the image's top-left corner), the light
// model's ratios there (SeenShift's color and beaming, 1 for the geometric
// light); `known` false where the ray (or a ray it is extrapolated from)
// did not reach the sky.
struct GridNode {
  Vec3 sky{};
  double x = 0.0, y = 0.0;
  float color = 1.0f, beaming = 1.0f;
  bool known = false;
};

// The grid over a frame's rays, its nodes made when asked (a frame's worth
// of nodes would be ~50 MB to write and read again).
class RayGrid {
 public:
  // rays: one per pixel, row by row, width x height (width, height >= 2),
  // kept by reference: they must outlive the grid.
  RayGrid(std::span<const SkyPoint> rays, int width, int height, ImageWrap wrap = {})
      : rays_(rays), w_(width), h_(height), wrap_(wrap) {
    if (wrap_.poles) {
      top_ = pole(0);
      bottom_ = pole(h_ - 1);
    }
  }

  int width() const { return w_; }
  int height() const { return h_; }
  const ImageWrap& wrap() const { return wrap_; }

  // The node at (i, j), -1 <= i <= width, -1 <= j <= height: inside the
  // image, pixel (i, j)'s ray; outside, extrapolated linearly (direction and
  // image point) from the two nearest nodes inside, stepping back into the
  // image along each axis that is outside, with the nearer one's light
  // ratios; unknown when either of those is.
  // Where the image wraps: column -1 is column width - 1 and column width
  // is column 0, their image points a width to the left or right; row -1
  // (row height) is the pole: its direction where the top (bottom) row's
  // rays converge, at the image's edge (y = 0 or height) below (above)
  // its column's node, with that node's light ratios.
  GridNode at(int i, int j) const {
    if (i >= 0 && j >= 0 && i < w_ && j < h_) return inside(i, j);
    if (wrap_.columns && (i < 0 || i >= w_)) {
      const int shift = i < 0 ? w_ : -w_;
      GridNode n = at(i + shift, j);
      n.x -= shift;
      return n;
    }
    if (wrap_.poles && (j < 0 || j >= h_)) {
      const GridNode& p = j < 0 ? top_ : bottom_;
      GridNode n = at(i, j < 0 ? 0 : h_ - 1);
      n.known = n.known && p.known;
      n.sky = p.sky;
      n.y = j < 0 ? 0.0 : h_;
      return n;
    }
    const int i0 = std::clamp(i, 0, w_ - 1), j0 = std::clamp(j, 0, h_ - 1);
    const int i1 = i < 0 ? 1 : i >= w_ ? w_ - 2 : i0, j1 = j < 0 ? 1 : j >= h_ ? h_ - 2 : j0;
    const GridNode a = inside(i0, j0), b = inside(i1, j1);
    if (!a.known || !b.known) return {};
    GridNode n = a;
    for (int k = 0; k < 3; ++k) n.sky[k] = 2 * a.sky[k] - b.sky[k];
    n.sky = unit3(n.sky);
    n.x = 2 * a.x - b.x;
    n.y = 2 * a.y - b.y;
    return n;
  }

 private:
  // Pixel (i, j)'s ray as a node (0 <= i < width, 0 <= j < height).
  GridNode inside(int i, int j) const {
    const SkyPoint& p = rays_[static_cast<std::size_t>(j) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(i)];
    if (!p.reached()) return {};
    const double s = std::sin(p.theta);
    return {{s * std::cos(p.phi), s * std::sin(p.phi), std::cos(p.theta)}, i + p.dx, j + p.dy, p.color, p.beaming, true};
  }

  // The pole beyond row j (0 or height - 1): the unit mean of the row's
  // rays' directions.  They ring the pole's own ray closely, so their mean
  // is its direction to second order in the ring's size; unknown where any
  // of them did not reach the sky.
  GridNode pole(int j) const {
    GridNode p;
    p.known = true;
    for (int i = 0; i < w_ && p.known; ++i) {
      const GridNode n = inside(i, j);
      p.known = n.known;
      for (int k = 0; k < 3; ++k) p.sky[k] += n.sky[k];
    }
    if (p.known) p.sky = unit3(p.sky);
    return p;
  }

  std::span<const SkyPoint> rays_;
  int w_, h_;
  ImageWrap wrap_;
  GridNode top_, bottom_;  // the poles, where wrap_.poles
};

}  // namespace lc
