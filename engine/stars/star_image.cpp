#include "stars/star_image.hpp"

#include <algorithm>

namespace lc {

std::optional<std::array<double, 2>> place_in_patch(const SkyPatch& patch, const Vec3& d) {
  const auto uv = patch.sky.locate(d);
  if (!uv || (*uv)[0] >= 1.0 - locate_slack || (*uv)[1] >= 1.0 - locate_slack) return std::nullopt;
  return std::array<double, 2>{std::clamp((*uv)[0], 0.0, 1.0), std::clamp((*uv)[1], 0.0, 1.0)};
}

StarImage image_at(const SkyPatch& patch, const std::array<double, 2>& uv, const std::array<double, 4>& mu) {
  const double u = uv[0], v = uv[1];
  const double wt[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
  double m = 0.0, x = 0.0, y = 0.0, colour = 0.0, beaming = 0.0;
  for (std::size_t k = 0; k < 4; ++k) {
    m += wt[k] * mu[k];
    x += wt[k] * patch.corner[k].x;
    y += wt[k] * patch.corner[k].y;
    colour += wt[k] * patch.corner[k].color;
    beaming += wt[k] * patch.corner[k].beaming;
  }
  return {x, y, m, colour, beaming};
}

}  // namespace lc
