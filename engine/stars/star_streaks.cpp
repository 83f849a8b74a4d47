#include "stars/star_streaks.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>

namespace lc {

namespace {

// The step from a to b (pixel units); on an image wrapped in columns the
// shorter way round.
std::array<double, 2> step_between(const FoundStarImage& a, const FoundStarImage& b, int width, const ImageWrap& wrap) {
  double dx = b.x - a.x;
  if (wrap.columns) dx -= width * std::round(dx / width);
  return {dx, b.y - a.y};
}

// The images of one instant sorted by star (then by their index, so the
// order is fixed), for looking a star's images up.
std::vector<std::pair<std::size_t, std::size_t>> by_star(const std::vector<FoundStarImage>& images) {
  std::vector<std::pair<std::size_t, std::size_t>> sorted;
  sorted.reserve(images.size());
  for (std::size_t k = 0; k < images.size(); ++k) sorted.emplace_back(images[k].star, k);
  std::sort(sorted.begin(), sorted.end());
  return sorted;
}

// The index of the image of `image`'s star in `others` nearest to it (ties:
// the first in index order), or nullopt when the star has none there.
std::optional<std::size_t> nearest_of_star(const FoundStarImage& image, const std::vector<FoundStarImage>& others,
                                           const std::vector<std::pair<std::size_t, std::size_t>>& others_by_star,
                                           int width, const ImageWrap& wrap) {
  auto it = std::lower_bound(others_by_star.begin(), others_by_star.end(), std::pair<std::size_t, std::size_t>{image.star, 0});
  std::optional<std::size_t> best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (; it != others_by_star.end() && it->first == image.star; ++it) {
    const auto d = step_between(image, others[it->second], width, wrap);
    const double d2 = d[0] * d[0] + d[1] * d[1];
    if (d2 < best_d2) {
      best_d2 = d2;
      best = it->second;
    }
  }
  return best;
}

}  // namespace

std::vector<std::vector<StreakPath>> star_streaks(std::span<const std::vector<FoundStarImage>> instants, int width,
                                                  int height, const ImageWrap& wrap) {
  const std::size_t K = instants.size();
  const double farthest = 0.25 * std::max(width, height);
  std::vector<std::vector<std::pair<std::size_t, std::size_t>>> sorted;
  for (const auto& images : instants) sorted.push_back(by_star(images));
  // next[k][i]: the step from image i of instant k to its match at k + 1.
  std::vector<std::vector<std::optional<std::array<double, 2>>>> next(K), previous(K);
  for (std::size_t k = 0; k < K; ++k) {
    next[k].assign(instants[k].size(), std::nullopt);
    previous[k].assign(instants[k].size(), std::nullopt);
  }
  for (std::size_t k = 0; k + 1 < K; ++k)
    for (std::size_t i = 0; i < instants[k].size(); ++i) {
      const FoundStarImage& a = instants[k][i];
      const auto j = nearest_of_star(a, instants[k + 1], sorted[k + 1], width, wrap);
      if (!j) continue;
      const auto back = nearest_of_star(instants[k + 1][*j], instants[k], sorted[k], width, wrap);
      if (back != i) continue;
      const auto d = step_between(a, instants[k + 1][*j], width, wrap);
      if (!(std::hypot(d[0], d[1]) < farthest)) continue;
      next[k][i] = d;
      previous[k + 1][*j] = d;
    }
  std::vector<std::vector<StreakPath>> paths(K);
  for (std::size_t k = 0; k < K; ++k) {
    paths[k].reserve(instants[k].size());
    for (std::size_t i = 0; i < instants[k].size(); ++i) {
      const FoundStarImage& image = instants[k][i];
      // Half a step each way; at the shutter's ends the one step there is.
      std::optional<std::array<double, 2>> back = previous[k][i], on = next[k][i];
      if (!back && k == 0) back = next[k][i];
      if (!on && k + 1 == K) on = previous[k][i];
      StreakPath p{{image.x, image.y}, {image.x, image.y}};
      if (back) p.before = {image.x - 0.5 * (*back)[0], image.y - 0.5 * (*back)[1]};
      if (on) p.after = {image.x + 0.5 * (*on)[0], image.y + 0.5 * (*on)[1]};
      paths[k].push_back(p);
    }
  }
  return paths;
}

}  // namespace lc
