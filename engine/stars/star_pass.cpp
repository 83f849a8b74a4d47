#include "stars/star_pass.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "stars/sky_quad.hpp"

namespace lc {

namespace {

Vec3 sky_direction(const SkyPoint& p) {
  const double s = std::sin(p.theta);
  return {s * std::cos(p.phi), s * std::sin(p.phi), std::cos(p.theta)};
}

// A point of the grid: where its ray went, the image point it went
// through and how the sky's light is seen there.
struct Node {
  Vec3 sky;
  double x, y;
  float color, beaming;
};

// The grid of rays one pixel wider on every side: inside, the frame's;
// outside, extrapolated linearly from the two nearest inside (where both
// reached the sky).
class Grid {
 public:
  Grid(std::span<const SkyPoint> sky, int w, int h) : sky_(sky), w_(w), h_(h) {}

  // The node at (i, j), -1 <= i <= w, -1 <= j <= h, if its ray (or both
  // rays it is extrapolated from) reached the sky.
  std::optional<Node> at(int i, int j) const {
    if (i >= 0 && i < w_ && j >= 0 && j < h_) return inside(i, j);
    // Step back into the image along each axis that is outside.
    const int i0 = std::clamp(i, 0, w_ - 1), j0 = std::clamp(j, 0, h_ - 1);
    const int i1 = i < 0 ? 1 : i >= w_ ? w_ - 2 : i0, j1 = j < 0 ? 1 : j >= h_ ? h_ - 2 : j0;
    if (i1 < 0 || i1 >= w_ || j1 < 0 || j1 >= h_) return std::nullopt;
    const auto a = inside(i0, j0), b = inside(i1, j1);
    if (!a || !b) return std::nullopt;
    Node n = *a;
    for (int k = 0; k < 3; ++k) n.sky[k] = 2 * a->sky[k] - b->sky[k];
    n.sky = unit3(n.sky);
    n.x = 2 * a->x - b->x;
    n.y = 2 * a->y - b->y;
    return n;
  }

 private:
  std::optional<Node> inside(int i, int j) const {
    const SkyPoint& p = sky_[static_cast<std::size_t>(j) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(i)];
    if (!p.reached()) return std::nullopt;
    return Node{sky_direction(p), i + p.dx, j + p.dy, p.color, p.beaming};
  }
  std::span<const SkyPoint> sky_;
  int w_, h_;
};

// A quad of the grid whose four rays reached the sky: its patch of sky,
// the patch's centre and angular radius, and its corners.
struct Quad {
  SkyQuad sky;
  Vec3 centre;
  double reach;
  std::array<const Node*, 4> corner;
};

// f(i, j, quad) for each quad (i, j) .. (i + 1, j + 1), i in [-1, w), j in
// [-1, h), whose four nodes are known and whose patch is no wider than
// max_reach (rad, centre to corner), row by row.
template <class F>
void for_each_quad(const Grid& grid, int w, int h, double max_reach, F&& f) {
  const double cos_reach = std::cos(max_reach);
  // The nodes of two rows at a time: a quad row needs its own and the next.
  std::vector<std::optional<Node>> upper(static_cast<std::size_t>(w + 2)), lower(upper.size());
  for (int i = -1; i <= w; ++i) upper[static_cast<std::size_t>(i + 1)] = grid.at(i, -1);
  for (int j = -1; j < h; ++j) {
    for (int i = -1; i <= w; ++i) lower[static_cast<std::size_t>(i + 1)] = grid.at(i, j + 1);
    for (int i = -1; i < w; ++i) {
      const auto& a = upper[static_cast<std::size_t>(i + 1)];
      const auto& b = upper[static_cast<std::size_t>(i + 2)];
      const auto& c = lower[static_cast<std::size_t>(i + 2)];
      const auto& d = lower[static_cast<std::size_t>(i + 1)];
      if (!a || !b || !c || !d) continue;
      Quad q{SkyQuad{{a->sky, b->sky, c->sky, d->sky}}, {}, 0.0, {&*a, &*b, &*c, &*d}};
      Vec3 sum{0, 0, 0};
      for (const Vec3& k : q.sky.c)
        for (int m = 0; m < 3; ++m) sum[m] += k[m];
      q.centre = unit3(sum);
      double least = 1.0;
      for (const Vec3& k : q.sky.c) least = std::min(least, dot3(k, q.centre));
      if (least < cos_reach) continue;
      q.reach = std::acos(std::clamp(least, -1.0, 1.0));
      f(i, j, q);
    }
    std::swap(upper, lower);
  }
}

// The halo of the glare: (1 + r^2 / a^2)^-2 on the pixels within 8 a
// (at least the 3 x 3 around the centre), normalised to 1.
struct GlareKernel {
  int radius;
  std::vector<double> weight;  // (2 radius + 1)^2, row by row
  explicit GlareKernel(double a) {
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
  }
};

}  // namespace

long add_point_stars(std::span<const SkyPoint> sky, int width, int height, const StarField& field,
                     const CameraDirections& camera, const StarPassOptions& options, std::span<float> rgb) {
  const int w = width, h = height;
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (w < 2 || h < 2 || sky.size() != pixels || rgb.size() != 3 * pixels)
    throw std::invalid_argument("star pass: the frame's rays or pixels do not match its size (at least 2 x 2)");
  const Grid grid(sky, w, h);
  // The camera's and the sky's solid angles of each quad, at (i + 1, j + 1)
  // (0 where the quad is not used).
  const std::size_t qw = static_cast<std::size_t>(w + 1), qh = static_cast<std::size_t>(h + 1);
  std::vector<std::array<double, 2>> area(qw * qh, {0.0, 0.0});
  auto quad_index = [&](int i, int j) { return static_cast<std::size_t>(j + 1) * qw + static_cast<std::size_t>(i + 1); };
  for_each_quad(grid, w, h, options.max_patch_radius, [&](int i, int j, const Quad& q) {
    const auto& k = q.corner;
    const SkyQuad seen{{camera(k[0]->x, k[0]->y), camera(k[1]->x, k[1]->y), camera(k[2]->x, k[2]->y),
                        camera(k[3]->x, k[3]->y)}};
    area[quad_index(i, j)] = {seen.area(), q.sky.area()};
  });
  // The magnification at each node (i, j), -1 <= i <= w, -1 <= j <= h (at
  // (i + 1, j + 1)): the camera's over the sky's solid angle of the quads
  // around it.
  const std::size_t nw = static_cast<std::size_t>(w + 2);
  std::vector<double> mu(nw * static_cast<std::size_t>(h + 2), 0.0);
  for (int j = -1; j <= h; ++j)
    for (int i = -1; i <= w; ++i) {
      double cam = 0.0, sky_area = 0.0;
      for (int qj = std::max(-1, j - 1); qj <= std::min(h - 1, j); ++qj)
        for (int qi = std::max(-1, i - 1); qi <= std::min(w - 1, i); ++qi) {
          cam += area[quad_index(qi, qj)][0];
          sky_area += area[quad_index(qi, qj)][1];
        }
      if (cam > 0.0)
        mu[static_cast<std::size_t>(j + 1) * nw + static_cast<std::size_t>(i + 1)] =
            cam / std::max(sky_area, cam / options.max_magnification);
    }
  auto mu_at = [&](int i, int j) { return mu[static_cast<std::size_t>(j + 1) * nw + static_cast<std::size_t>(i + 1)]; };
  // Each image's light, before glare: per pixel, flux (the pass divides by
  // the pixel's solid angle at the end).
  std::vector<Color> flux(pixels, Color{0, 0, 0});
  long images = 0;
  for_each_quad(grid, w, h, options.max_patch_radius, [&](int i, int j, const Quad& q) {
    const double m4[4] = {mu_at(i, j), mu_at(i + 1, j), mu_at(i + 1, j + 1), mu_at(i, j + 1)};
    field.bins().near(q.centre, q.reach, [&](std::size_t s) {
      const auto uv = q.sky.locate(field.stars()[s].direction);
      // A star on an edge two quads share is counted in one: the one
      // where it is at u = 0 (v = 0).
      if (!uv || (*uv)[0] >= 1.0 - locate_slack || (*uv)[1] >= 1.0 - locate_slack) return;
      const double u = std::clamp((*uv)[0], 0.0, 1.0), v = std::clamp((*uv)[1], 0.0, 1.0);
      const double wt[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
      double m = 0.0, x = 0.0, y = 0.0, colour = 0.0, beaming = 0.0;
      for (std::size_t k = 0; k < 4; ++k) {
        m += wt[k] * m4[k];
        x += wt[k] * q.corner[k]->x;
        y += wt[k] * q.corner[k]->y;
        colour += wt[k] * q.corner[k]->color;
        beaming += wt[k] * q.corner[k]->beaming;
      }
      const Color light = field.seen(s, static_cast<float>(colour), static_cast<float>(beaming));
      // Tent filter: the pixels whose centres are within one pixel.
      const double fx = x - 0.5, fy = y - 0.5;
      const int px = static_cast<int>(std::floor(fx)), py = static_cast<int>(std::floor(fy));
      const double ax = fx - px, ay = fy - py;
      for (int k = 0; k < 4; ++k) {
        const int pi_ = px + (k & 1), pj = py + (k >> 1);
        if (pi_ < 0 || pj < 0 || pi_ >= w || pj >= h) continue;
        const double share = m * ((k & 1) ? ax : 1 - ax) * ((k >> 1) ? ay : 1 - ay);
        Color& f = flux[static_cast<std::size_t>(pj) * static_cast<std::size_t>(w) + static_cast<std::size_t>(pi_)];
        for (int c = 0; c < 3; ++c) f[c] += static_cast<float>(share * light[c]);
      }
      ++images;
    });
  });
  // Glare, then flux to radiance: over each pixel's solid angle.
  if (options.glare > 0.0) {
    const GlareKernel kernel(options.glare_radius);
    std::vector<Color> halo(pixels, Color{0, 0, 0});
    const int r = kernel.radius, n = 2 * r + 1;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        Color& f = flux[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i)];
        if (f[0] == 0.0f && f[1] == 0.0f && f[2] == 0.0f) continue;
        Color spread;
        for (int c = 0; c < 3; ++c) {
          spread[c] = static_cast<float>(options.glare * f[c]);
          f[c] -= spread[c];
        }
        for (int dy = std::max(-r, -j); dy <= std::min(r, h - 1 - j); ++dy)
          for (int dx = std::max(-r, -i); dx <= std::min(r, w - 1 - i); ++dx) {
            const double k = kernel.weight[static_cast<std::size_t>((dy + r) * n + dx + r)];
            if (k == 0.0) continue;
            Color& t = halo[static_cast<std::size_t>(j + dy) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i + dx)];
            for (int c = 0; c < 3; ++c) t[c] += static_cast<float>(k * spread[c]);
          }
      }
    for (std::size_t p = 0; p < pixels; ++p)
      for (int c = 0; c < 3; ++c) flux[p][c] += halo[p][c];
  }
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const std::size_t p = static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i);
      if (flux[p][0] == 0.0f && flux[p][1] == 0.0f && flux[p][2] == 0.0f) continue;
      const double omega = SkyQuad{{camera(i, j), camera(i + 1, j), camera(i + 1, j + 1), camera(i, j + 1)}}.area();
      for (int c = 0; c < 3; ++c) rgb[3 * p + static_cast<std::size_t>(c)] += static_cast<float>(flux[p][c] / omega);
    }
  return images;
}

}  // namespace lc
