#pragma once
// The halo of a star's glare (docs/stars.md, "How a frame draws them", 6):
// (1 + r^2 / a^2)^-2 of scale a pixels on the pixels within 8 a (at least the
// 3 x 3 around the centre), normalised to 1, with what the star pass needs
// to cut it short where it is too faint (stars/pixel_light.hpp).

#include <vector>

namespace lc {

struct GlareKernel {
  // a: the halo's scale in pixels, > 0.
  explicit GlareKernel(double a);

  int radius;                     // pixels, each way
  std::vector<double> weight;     // (2 radius + 1)^2, row by row
  std::vector<double> at_radius;  // the weight at r pixels straight out, r = 0 .. radius
  std::vector<double> within;     // the weights' sum over the square of half-side r
};

}  // namespace lc
