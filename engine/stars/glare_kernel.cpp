#include "stars/glare_kernel.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace lc {

GlareKernel::GlareKernel(double a) {
  radius = std::max(1, static_cast<int>(std::ceil(8.0 * a)));
  const int n = 2 * radius + 1;
  weight.resize(static_cast<std::size_t>(n * n));
  double sum = 0.0;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const double q = 1.0 + (dx * dx + dy * dy) / (a * a);
      const double v = dx * dx + dy * dy <= radius * radius ? 1.0 / (q * q) : 0.0;
      weight[static_cast<std::size_t>((dy + radius) * n + dx + radius)] = v;
      sum += v;
    }
  for (double& v : weight) v /= sum;
  at_radius.resize(static_cast<std::size_t>(radius + 1));
  within.assign(static_cast<std::size_t>(radius + 1), 0.0);
  for (int r = 0; r <= radius; ++r) {
    const double q = 1.0 + r * r / (a * a);
    at_radius[static_cast<std::size_t>(r)] = 1.0 / (q * q * sum);
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx)
        within[static_cast<std::size_t>(r)] += weight[static_cast<std::size_t>((dy + radius) * n + dx + radius)];
  }
}

}  // namespace lc
