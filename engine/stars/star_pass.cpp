#include "stars/star_pass.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "stars/sky_quad.hpp"

namespace lc {

namespace {

Vec3 normalised(const Vec3& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}
double dot3(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// The grid of directions one pixel wider on every side: inside, the pixel
// centres'; outside, extrapolated linearly from the two nearest inside
// (where both reached the sky).
class ExtendedGrid {
 public:
  explicit ExtendedGrid(const SkyDirections& sky) : sky_(sky) {}

  // The direction at (i, j), -1 <= i <= width, -1 <= j <= height, if known.
  std::optional<Vec3> at(int i, int j) const {
    const int w = sky_.width, h = sky_.height;
    if (i >= 0 && i < w && j >= 0 && j < h) return inside(i, j);
    // Step back into the image along each axis that is outside.
    const int i0 = std::clamp(i, 0, w - 1), j0 = std::clamp(j, 0, h - 1);
    const int i1 = i < 0 ? 1 : i >= w ? w - 2 : i0, j1 = j < 0 ? 1 : j >= h ? h - 2 : j0;
    if (i1 < 0 || i1 >= w || j1 < 0 || j1 >= h) return std::nullopt;
    const auto a = inside(i0, j0), b = inside(i1, j1);
    if (!a || !b) return std::nullopt;
    return normalised({2 * (*a)[0] - (*b)[0], 2 * (*a)[1] - (*b)[1], 2 * (*a)[2] - (*b)[2]});
  }

 private:
  std::optional<Vec3> inside(int i, int j) const {
    const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(sky_.width) + static_cast<std::size_t>(i);
    if (!sky_.reached[k]) return std::nullopt;
    return sky_.direction[k];
  }
  const SkyDirections& sky_;
};

}  // namespace

long add_point_stars(const SkyDirections& sky, std::span<const PointStar> stars, const StarBins& bins,
                     const StarPassOptions& options, std::span<Color> radiance) {
  const ExtendedGrid grid(sky);
  long images = 0;
  auto deposit = [&](int i, int j, double weight, const Color& flux) {
    if (i < 0 || j < 0 || i >= sky.width || j >= sky.height || weight <= 0.0) return;
    Color& p = radiance[static_cast<std::size_t>(j) * static_cast<std::size_t>(sky.width) + static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c) p[c] += static_cast<float>(weight * flux[c]);
  };
  // Quads between centres (i, j) .. (i + 1, j + 1), i from -1 to width - 1.
  for (int j = -1; j < sky.height; ++j)
    for (int i = -1; i < sky.width; ++i) {
      const auto a = grid.at(i, j), b = grid.at(i + 1, j), c = grid.at(i + 1, j + 1), d = grid.at(i, j + 1);
      if (!a || !b || !c || !d) continue;
      const SkyQuad quad{{*a, *b, *c, *d}};
      const Vec3 centre = normalised({(*a)[0] + (*b)[0] + (*c)[0] + (*d)[0], (*a)[1] + (*b)[1] + (*c)[1] + (*d)[1],
                                      (*a)[2] + (*b)[2] + (*c)[2] + (*d)[2]});
      double reach = 0.0;
      for (const Vec3& k : quad.c) reach = std::max(reach, std::acos(std::clamp(dot3(k, centre), -1.0, 1.0)));
      if (reach > options.max_patch_radius) continue;
      // Radiance added to a pixel: F mu w / Omega_pixel = F w / Omega_patch,
      // with mu clamped at caustics.
      const double patch = std::max(quad.area(), options.pixel_solid_angle / options.max_magnification);
      const double scale = 1.0 / patch;
      bins.near(centre, reach, [&](std::size_t s) {
        const PointStar& star = stars[s];
        const auto uv = quad.locate(star.direction);
        // A star on an edge two quads share is counted in one: the one
        // where it is at u = 0 (v = 0).
        if (!uv || (*uv)[0] >= 1.0 - locate_slack || (*uv)[1] >= 1.0 - locate_slack) return;
        const double u = std::clamp((*uv)[0], 0.0, 1.0), v = std::clamp((*uv)[1], 0.0, 1.0);
        deposit(i, j, scale * (1 - u) * (1 - v), star.flux);
        deposit(i + 1, j, scale * u * (1 - v), star.flux);
        deposit(i + 1, j + 1, scale * u * v, star.flux);
        deposit(i, j + 1, scale * (1 - u) * v, star.flux);
        ++images;
      });
    }
  return images;
}

}  // namespace lc
