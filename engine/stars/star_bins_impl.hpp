#pragma once
// StarBins::for_cells, a template (included by stars/star_bins.hpp).

#include <algorithm>
#include <cmath>

#include "core/constants.hpp"
#include "stars/star_bins.hpp"

namespace lc {

template <class G>
void StarBins::for_cells(const Vec3& centre, double radius, G&& g) const {
  const double theta = std::acos(std::clamp(centre[2], -1.0, 1.0));
  const double phi = std::atan2(centre[1], centre[0]);
  const double height = pi / bands_;
  const int b0 = std::max(0, static_cast<int>(std::floor((theta - radius) / height)));
  const int b1 = std::min(bands_ - 1, static_cast<int>(std::floor((theta + radius) / height)));
  // The cap's greatest reach in phi from its centre (over all its points):
  // asin(sin r / sin theta), or every phi where it holds a pole.
  const bool pole = theta - radius <= 0.0 || theta + radius >= pi;
  const double half = pole ? pi : std::asin(std::min(1.0, std::sin(radius) / std::sin(theta)));
  for (int b = b0; b <= b1; ++b) {
    const int n = columns_[static_cast<std::size_t>(b)];
    const std::size_t first = first_[static_cast<std::size_t>(b)];
    if (half >= pi || n == 1) {
      for (int c = 0; c < n; ++c) g(first + static_cast<std::size_t>(c));
      continue;
    }
    const double width = two_pi / n;
    const int c0 = static_cast<int>(std::floor((phi - half) / width)), c1 = static_cast<int>(std::floor((phi + half) / width));
    if (c1 - c0 + 1 >= n) {
      for (int c = 0; c < n; ++c) g(first + static_cast<std::size_t>(c));
      continue;
    }
    for (int c = c0; c <= c1; ++c) g(first + static_cast<std::size_t>(((c % n) + n) % n));
  }
}

}  // namespace lc
