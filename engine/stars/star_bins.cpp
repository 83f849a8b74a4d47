#include "stars/star_bins.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/constants.hpp"

namespace lc {

StarBins::StarBins(const std::vector<Vec3>& directions, double cell) {
  if (!(cell > 0.0)) throw std::invalid_argument("star bins: the cell size must be > 0");
  bands_ = std::max(1, static_cast<int>(std::ceil(pi / cell)));
  const double height = pi / bands_;
  std::size_t cells = 0;
  for (int b = 0; b < bands_; ++b) {
    // As many cells as the band's widest circle holds at its height.
    const double lo = b * height, hi = (b + 1) * height;
    const double widest = lo <= 0.5 * pi && hi >= 0.5 * pi ? 1.0 : std::max(std::sin(lo), std::sin(hi));
    const int n = std::max(1, static_cast<int>(std::ceil(two_pi * widest / height)));
    columns_.push_back(n);
    first_.push_back(cells);
    cells += static_cast<std::size_t>(n);
  }
  std::vector<std::size_t> where(directions.size());
  std::vector<std::uint32_t> count(cells + 1, 0);
  for (std::size_t k = 0; k < directions.size(); ++k) {
    const Vec3& d = directions[k];
    double phi = std::atan2(d[1], d[0]);
    if (phi < 0.0) phi += two_pi;
    where[k] = cell_of(std::acos(std::clamp(d[2], -1.0, 1.0)), phi);
    ++count[where[k] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) count[c + 1] += count[c];
  start_ = count;
  index_.resize(directions.size());
  std::vector<std::uint32_t> next(count.begin(), count.end() - 1);
  for (std::size_t k = 0; k < directions.size(); ++k) index_[next[where[k]]++] = static_cast<std::uint32_t>(k);
}

std::size_t StarBins::cell_of(double theta, double phi) const {
  const int b = std::min(bands_ - 1, static_cast<int>(theta / (pi / bands_)));
  const int n = columns_[static_cast<std::size_t>(b)];
  const int c = std::min(n - 1, static_cast<int>(phi / (two_pi / n)));
  return first_[static_cast<std::size_t>(b)] + static_cast<std::size_t>(c);
}

}  // namespace lc
