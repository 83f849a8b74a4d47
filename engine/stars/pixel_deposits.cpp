#include "stars/pixel_deposits.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace lc {

void splat_tent(double x, double y, double magnification, const Color& flux, int width, int height,
                const ImageWrap& wrap, std::vector<Deposit>& out) {
  const double fx = x - 0.5, fy = y - 0.5;
  const int px = static_cast<int>(std::floor(fx)), py = static_cast<int>(std::floor(fy));
  const double ax = fx - px, ay = fy - py;
  for (int k = 0; k < 4; ++k) {
    int pi_ = px + (k & 1), pj = py + (k >> 1);
    if (wrap.poles && (pj < 0 || pj >= height)) {
      pj = pj < 0 ? -1 - pj : 2 * height - 1 - pj;
      pi_ += width / 2;
    }
    if (wrap.columns) pi_ = ((pi_ % width) + width) % width;
    if (pi_ < 0 || pj < 0 || pi_ >= width || pj >= height) continue;
    const double share = magnification * ((k & 1) ? ax : 1 - ax) * ((k >> 1) ? ay : 1 - ay);
    Deposit d{pi_, pj, {}};
    for (int c = 0; c < 3; ++c) d.flux[c] = static_cast<float>(share * flux[c]);
    out.push_back(d);
  }
}

void sum_deposits_per_pixel(std::vector<Deposit>& deposits) {
  std::sort(deposits.begin(), deposits.end(),
            [](const Deposit& x, const Deposit& y) { return x.j != y.j ? x.j < y.j : x.i < y.i; });
  std::size_t kept = 0;
  for (std::size_t k = 0; k < deposits.size(); ++k) {
    if (kept > 0 && deposits[kept - 1].i == deposits[k].i && deposits[kept - 1].j == deposits[k].j) {
      for (int c = 0; c < 3; ++c) deposits[kept - 1].flux[c] += deposits[k].flux[c];
    } else {
      deposits[kept++] = deposits[k];
    }
  }
  deposits.resize(kept);
}

}  // namespace lc
