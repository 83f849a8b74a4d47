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
  const int w = sky.width, h = sky.height;
  // Quads (i, j) .. (i + 1, j + 1) for i in [-1, w), j in [-1, h), stored at
  // (i + 1, j + 1): their patches of sky, or none.
  const int qw = w + 1, qh = h + 1;
  std::vector<std::optional<SkyQuad>> quads(static_cast<std::size_t>(qw * qh));
  std::vector<double> area(quads.size(), 0.0);
  for (int j = -1; j < h; ++j)
    for (int i = -1; i < w; ++i) {
      const auto a = grid.at(i, j), b = grid.at(i + 1, j), c = grid.at(i + 1, j + 1), d = grid.at(i, j + 1);
      if (!a || !b || !c || !d) continue;
      const SkyQuad quad{{*a, *b, *c, *d}};
      const Vec3 centre = normalised({(*a)[0] + (*b)[0] + (*c)[0] + (*d)[0], (*a)[1] + (*b)[1] + (*c)[1] + (*d)[1],
                                      (*a)[2] + (*b)[2] + (*c)[2] + (*d)[2]});
      double reach = 0.0;
      for (const Vec3& k : quad.c) reach = std::max(reach, std::acos(std::clamp(dot3(k, centre), -1.0, 1.0)));
      if (reach > options.max_patch_radius) continue;
      const std::size_t q = static_cast<std::size_t>((j + 1) * qw + (i + 1));
      quads[q] = quad;
      area[q] = quad.area();
    }
  // Each pixel centre's density of pixels on the sky, rho = 1 / (its share
  // of sky: the mean of the patches around it), for nodes -1 .. w, -1 .. h.
  // At a star, rho interpolated from the quad's corners is mu / Omega_camera
  // to second order, where one patch's 1 / area is only first order (and
  // off by several percent on a demagnified image whose mu changes fast).
  const double floor_area = options.pixel_solid_angle / options.max_magnification;
  auto density = [&](int i, int j) {
    double sum = 0.0;
    int n = 0;
    for (int dj = -1; dj <= 0; ++dj)
      for (int di = -1; di <= 0; ++di) {
        const int qi = i + di, qj = j + dj;
        if (qi < -1 || qj < -1 || qi >= w || qj >= h) continue;
        const std::size_t q = static_cast<std::size_t>((qj + 1) * qw + (qi + 1));
        if (!quads[q]) continue;
        sum += area[q];
        ++n;
      }
    return n ? 1.0 / std::max(sum / n, floor_area) : 0.0;
  };
  long images = 0;
  auto deposit = [&](int i, int j, double weight, const Color& flux) {
    if (i < 0 || j < 0 || i >= w || j >= h || weight <= 0.0) return;
    Color& p = radiance[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c) p[c] += static_cast<float>(weight * flux[c]);
  };
  for (int j = -1; j < h; ++j)
    for (int i = -1; i < w; ++i) {
      const auto& quad = quads[static_cast<std::size_t>((j + 1) * qw + (i + 1))];
      if (!quad) continue;
      const double rho[4] = {density(i, j), density(i + 1, j), density(i + 1, j + 1), density(i, j + 1)};
      const Vec3 centre = normalised({quad->c[0][0] + quad->c[1][0] + quad->c[2][0] + quad->c[3][0],
                                      quad->c[0][1] + quad->c[1][1] + quad->c[2][1] + quad->c[3][1],
                                      quad->c[0][2] + quad->c[1][2] + quad->c[2][2] + quad->c[3][2]});
      double reach = 0.0;
      for (const Vec3& k : quad->c) reach = std::max(reach, std::acos(std::clamp(dot3(k, centre), -1.0, 1.0)));
      bins.near(centre, reach, [&](std::size_t s) {
        const PointStar& star = stars[s];
        const auto uv = quad->locate(star.direction);
        // A star on an edge two quads share is counted in one: the one
        // where it is at u = 0 (v = 0).
        if (!uv || (*uv)[0] >= 1.0 - locate_slack || (*uv)[1] >= 1.0 - locate_slack) return;
        const double u = std::clamp((*uv)[0], 0.0, 1.0), v = std::clamp((*uv)[1], 0.0, 1.0);
        const double wt[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
        const double r = wt[0] * rho[0] + wt[1] * rho[1] + wt[2] * rho[2] + wt[3] * rho[3];
        deposit(i, j, r * wt[0], star.flux);
        deposit(i + 1, j, r * wt[1], star.flux);
        deposit(i + 1, j + 1, r * wt[2], star.flux);
        deposit(i, j + 1, r * wt[3], star.flux);
        ++images;
      });
    }
  return images;
}

}  // namespace lc
