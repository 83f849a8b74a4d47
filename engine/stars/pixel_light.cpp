#include "stars/pixel_light.hpp"

#include <algorithm>
#include <cstddef>

#include "core/parallel_for.hpp"

namespace lc {

std::vector<LitPixel> light_pixels(const std::vector<Deposit>& deposits, const CameraDirections& camera,
                                   const GlareSpread& spread, int threads, double& helpers_cpu) {
  std::vector<LitPixel> lit(deposits.size());
  const GlareKernel* kernel = spread.kernel;
  constexpr std::size_t chunk = 256;
  parallel_for((deposits.size() + chunk - 1) / chunk, {.threads = threads, .helpers_cpu = &helpers_cpu}, [&](std::size_t c) {
    for (std::size_t k = c * chunk; k < std::min(deposits.size(), (c + 1) * chunk); ++k) {
      const Deposit& d = deposits[k];
      const double omega = camera_solid_angle(camera, {{{static_cast<double>(d.i), static_cast<double>(d.j)},
                                                        {static_cast<double>(d.i + 1), static_cast<double>(d.j)},
                                                        {static_cast<double>(d.i + 1), static_cast<double>(d.j + 1)},
                                                        {static_cast<double>(d.i), static_cast<double>(d.j + 1)}}});
      LitPixel& l = lit[k];
      for (int m = 0; m < 3; ++m) l.radiance[m] = static_cast<float>(d.flux[m] / omega);
      if (!kernel) continue;
      // The halo as far as it is brighter than the floor (a faint image's
      // stops at once).
      const double glow = spread.glare * (0.2126 * l.radiance[0] + 0.7152 * l.radiance[1] + 0.0722 * l.radiance[2]);
      const double floor = spread.floor_share * spread.faintest / omega;
      while (l.reach < kernel->radius && glow * kernel->at_radius[static_cast<std::size_t>(l.reach + 1)] >= floor) ++l.reach;
      l.share = spread.glare / kernel->within[static_cast<std::size_t>(l.reach)];
    }
  });
  return lit;
}

void add_lit_pixels(const std::vector<Deposit>& deposits, const std::vector<LitPixel>& lit, const GlareSpread& spread,
                    int width, int height, int band, int threads, std::span<float> rgb, double& helpers_cpu) {
  const GlareKernel* kernel = spread.kernel;
  const int w = width, h = height;
  const int reach = kernel ? kernel->radius : 0;
  const int bands = (h + band - 1) / band;
  parallel_for(static_cast<std::size_t>(bands), {.threads = threads, .helpers_cpu = &helpers_cpu}, [&](std::size_t b) {
    const int y0 = static_cast<int>(b) * band, y1 = std::min(h, y0 + band);
    auto row_at_least = [&](int j) {
      return std::partition_point(deposits.begin(), deposits.end(), [j](const Deposit& d) { return d.j < j; }) -
             deposits.begin();
    };
    const auto first = row_at_least(y0 - reach), last = row_at_least(y1 + reach);
    for (auto k = first; k < last; ++k) {
      const Deposit& d = deposits[static_cast<std::size_t>(k)];
      const LitPixel& l = lit[static_cast<std::size_t>(k)];
      auto add = [&](int i, int j, float weight) {
        float* p = &rgb[3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i))];
        for (int m = 0; m < 3; ++m) p[m] += weight * l.radiance[m];
      };
      if (!kernel) {
        if (d.j >= y0 && d.j < y1) add(d.i, d.j, 1.0f);
        continue;
      }
      if (d.j >= y0 && d.j < y1) add(d.i, d.j, static_cast<float>(1.0 - spread.glare));
      const int r = l.reach, n = 2 * kernel->radius + 1, c0 = kernel->radius;
      for (int dy = std::max({-r, -d.j, y0 - d.j}); dy <= std::min({r, h - 1 - d.j, y1 - 1 - d.j}); ++dy)
        for (int dx = std::max(-r, -d.i); dx <= std::min(r, w - 1 - d.i); ++dx)
          if (const double k = kernel->weight[static_cast<std::size_t>((dy + c0) * n + dx + c0)]; k > 0.0)
            add(d.i + dx, d.j + dy, static_cast<float>(l.share * k));
    }
  });
}

}  // namespace lc
