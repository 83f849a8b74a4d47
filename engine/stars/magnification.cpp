#include "stars/magnification.hpp"

#include <algorithm>

#include "stars/sky_patch.hpp"

namespace lc {

PatchAreas Magnifications::areas(int i, int j) {
  // Across a wrapped seam quad -1 is quad width - 1 and quad width quad 0.
  if (grid_.wrap().columns) i = (i + grid_.width()) % grid_.width();
  const std::size_t key =
      static_cast<std::size_t>(j + 1) * static_cast<std::size_t>(grid_.width() + 1) + static_cast<std::size_t>(i + 1);
  if (const auto it = areas_.find(key); it != areas_.end()) return it->second;
  PatchAreas a;
  if (const auto q = patch_of(grid_, i, j, cos_max_)) {
    const auto& k = q->corner;
    a = {camera_solid_angle(camera_, {{{k[0].x, k[0].y}, {k[1].x, k[1].y}, {k[2].x, k[2].y}, {k[3].x, k[3].y}}}),
         q->sky.area()};
  }
  return areas_.emplace(key, a).first->second;
}

double Magnifications::at_node(int i, int j) {
  double seen = 0.0, sky_area = 0.0;
  for (int qj = std::max(-1, j - 1); qj <= std::min(grid_.height() - 1, j); ++qj)
    for (int qi = std::max(-1, i - 1); qi <= (grid_.wrap().columns ? i : std::min(grid_.width() - 1, i)); ++qi) {
      const PatchAreas a = areas(qi, qj);
      seen += a.camera;
      sky_area += a.sky;
    }
  return seen > 0.0 ? seen / std::max(sky_area, seen / max_magnification_) : 0.0;
}

double Magnifications::least_luminance_drawn(int i, int j, double invisible, double faintest) {
  const PatchAreas a = areas(i, j);
  return invisible * faintest * std::max(a.sky, a.camera / max_magnification_) / (2.0 * a.camera);
}

}  // namespace lc
