#pragma once
// The star pass's last stages (stars/star_pass.hpp; docs/stars.md, "How a
// frame draws them", 5 and 6): each lit pixel's flux (the summed deposits,
// stars/pixel_deposits.hpp) as radiance over the pixel's solid angle, with
// how far its glare's halo (stars/glare_kernel.hpp) is worth spreading; then
// the radiance and the halos added to the image.  The halo's pixels are
// taken as the same size as the lit one's: it spans a few pixels.

#include <span>
#include <vector>

#include "core/color.hpp"
#include "stars/camera_directions.hpp"
#include "stars/glare_kernel.hpp"
#include "stars/pixel_deposits.hpp"

namespace lc {

// A lit pixel's radiance, and how far (pixels) and with what weight its
// glare's halo spreads.
struct LitPixel {
  Color radiance{};
  int reach = 0;
  double share = 0.0;
};

// How the light is spread: `glare` of it into the halo of `kernel` (null:
// no glare), whose reach stops where it falls under `floor_share` of the
// faintest star's light (`faintest`, luminance) on one pixel, its weights
// scaled up to keep the light.
struct GlareSpread {
  const GlareKernel* kernel = nullptr;
  double glare = 0.0;
  double floor_share = 0.0;
  double faintest = 0.0;
};

// One LitPixel per deposit (summed per pixel, sorted by row), in their
// order; worked out in chunks on up to `threads` threads, whose CPU time
// beyond this one's is added to helpers_cpu.
std::vector<LitPixel> light_pixels(const std::vector<Deposit>& deposits, const CameraDirections& camera,
                                   const GlareSpread& spread, int threads, double& helpers_cpu);

// Adds each lit pixel's radiance (less the glare's share) and its halo to
// `rgb` (linear RGB, 3 floats per pixel, row by row, width x height), by
// bands of `band` rows on up to `threads` threads: each band from every lit
// pixel whose halo reaches it, in the lit pixels' order, so each pixel sums
// what lands on it in the order one thread would (the same to the bit on
// any number).
void add_lit_pixels(const std::vector<Deposit>& deposits, const std::vector<LitPixel>& lit, const GlareSpread& spread,
                    int width, int height, int band, int threads, std::span<float> rgb, double& helpers_cpu);

}  // namespace lc
