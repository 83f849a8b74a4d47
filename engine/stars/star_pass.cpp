#include "stars/star_pass.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <unordered_map>
#include <vector>

#include "core/constants.hpp"
#include "core/cpu_time.hpp"
#include "stars/sky_quad.hpp"

namespace lc {

namespace {

// A point of the grid: where its ray went, the image point it went
// through and how the sky's light is seen there; `known` false where the
// ray (or a ray it is extrapolated from) did not reach the sky.
struct Node {
  Vec3 sky{};
  double x = 0.0, y = 0.0;
  float color = 1.0f, beaming = 1.0f;
  bool known = false;
};

// The grid of rays one pixel wider on every side, made from the frame's
// rays when asked (a frame's worth of nodes would be ~50 MB to write and
// read again): inside, the frame's; outside, extrapolated linearly from the
// two nearest inside.
class Grid {
 public:
  Grid(std::span<const SkyPoint> rays, int w, int h) : rays_(rays), w_(w), h_(h) {}

  // The node at (i, j), -1 <= i <= w, -1 <= j <= h.
  Node at(int i, int j) const {
    if (i >= 0 && j >= 0 && i < w_ && j < h_) return inside(i, j);
    // Stepping back into the image along each axis that is outside.
    const int i0 = std::clamp(i, 0, w_ - 1), j0 = std::clamp(j, 0, h_ - 1);
    const int i1 = i < 0 ? 1 : i >= w_ ? w_ - 2 : i0, j1 = j < 0 ? 1 : j >= h_ ? h_ - 2 : j0;
    const Node a = inside(i0, j0), b = inside(i1, j1);
    if (!a.known || !b.known) return {};
    Node n = a;
    for (int k = 0; k < 3; ++k) n.sky[k] = 2 * a.sky[k] - b.sky[k];
    n.sky = unit3(n.sky);
    n.x = 2 * a.x - b.x;
    n.y = 2 * a.y - b.y;
    return n;
  }

 private:
  Node inside(int i, int j) const {
    const SkyPoint& p = rays_[static_cast<std::size_t>(j) * static_cast<std::size_t>(w_) + static_cast<std::size_t>(i)];
    if (!p.reached()) return {};
    const double s = std::sin(p.theta);
    return {{s * std::cos(p.phi), s * std::sin(p.phi), std::cos(p.theta)}, i + p.dx, j + p.dy, p.color, p.beaming, true};
  }
  std::span<const SkyPoint> rays_;
  int w_, h_;
};

// A quad of the grid whose four rays reached the sky: its patch of sky,
// the patch's centre and the cosine of its angular radius, its corners.
struct Quad {
  SkyQuad sky;
  Vec3 centre;
  double cos_reach;
  std::array<Node, 4> corner;
  // The planes of its edges (great circles), normals pointing in, when the
  // patch is convex (else `convex` is false and every star in its cap is
  // located): a star outside one is not in the patch, a cheap test before
  // SkyQuad::locate.
  std::array<Vec3, 4> inward;
  bool convex = false;

  bool may_hold(const Vec3& d) const {
    if (!convex) return true;
    for (const Vec3& n : inward)
      if (dot3(d, n) < -1e-9 * norm3(n)) return false;  // generous: locate decides on the edge
    return true;
  }
};

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// The quad of nodes a, b, c, d (in order around it) if all are known and
// its patch is no wider than the cosine cos_max says (centre to corner).
std::optional<Quad> make_quad(const Node& a, const Node& b, const Node& c, const Node& d, double cos_max) {
  if (!a.known || !b.known || !c.known || !d.known) return std::nullopt;
  Quad q{SkyQuad{{a.sky, b.sky, c.sky, d.sky}}, {}, 1.0, {a, b, c, d}};
  Vec3 sum{0, 0, 0};
  for (const Vec3& k : q.sky.c)
    for (int m = 0; m < 3; ++m) sum[m] += k[m];
  q.centre = unit3(sum);
  for (const Vec3& k : q.sky.c) q.cos_reach = std::min(q.cos_reach, dot3(k, q.centre));
  if (q.cos_reach < cos_max) return std::nullopt;
  // Edge k runs from corner k to k + 1; its plane's normal points to the
  // side of the centre, and every other corner must lie on that side.
  q.convex = true;
  for (int k = 0; k < 4; ++k) {
    Vec3 n = cross(q.sky.c[static_cast<std::size_t>(k)], q.sky.c[static_cast<std::size_t>((k + 1) % 4)]);
    if (dot3(n, q.centre) < 0.0)
      for (double& x : n) x = -x;
    for (int m = 2; m <= 3; ++m)
      if (dot3(n, q.sky.c[static_cast<std::size_t>((k + m) % 4)]) < 0.0) q.convex = false;
    q.inward[static_cast<std::size_t>(k)] = n;
  }
  return q;
}

// Tiles of quads searched together: one lookup in the star bins per tile,
// then each of its quads tests only the tile's stars; a tile with more
// than split_above of them is searched as four.
constexpr int tile = 16;
constexpr std::size_t split_above = 16;

// A tile whose nodes lie within this of their centre (rad) is searched in
// its tangent plane (a gnomonic projection stretches 1 / cos^2: 1.3 here).
constexpr double plane_tile = 30.0 * degree;

// A patch wider than this (centre to corner, rad) is searched alone: about
// a bin of the star field (stars/star_field.cpp).
constexpr double wide_patch = 1.0 * degree;

// Images fainter than this share of the faintest star's light are not
// drawn: 7.5 magnitudes under the faintest star the sky holds.
constexpr double invisible = 1e-3;

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
  std::vector<double> at_radius;  // the weight at r pixels straight out, r = 0 .. radius
  std::vector<double> within;     // the weights' sum over the square of half-side r
};

// Light landed on one pixel (its flux: radiance times its solid angle).
struct Deposit {
  int i, j;
  Color flux;
};

// What one row of tiles found: its deposits in the order it made them.
struct TileRow {
  std::vector<Deposit> deposits;
  long images = 0;
};

// A lit pixel's radiance, and how far (pixels) and with what weight its
// glare's halo spreads.
struct Lit {
  Color radiance{};
  int reach = 0;
  double share = 0.0;
};

// Runs fn(k) for every k in [0, count) once, on up to `threads` threads
// (this one among them) in no particular order; adds the CPU time the
// threads it started spent to `helpers_cpu` (this thread's own is the
// caller's to measure).  The first exception thrown is rethrown once all
// stop.
template <class F>
void for_each_parallel(std::size_t count, int threads, F&& fn, double& helpers_cpu) {
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::exception_ptr error;
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < count;) {
      try {
        fn(k);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        next = count;
      }
    }
  };
  const std::size_t helpers = count == 0 ? 0 : std::min(count, static_cast<std::size_t>(std::max(1, threads))) - 1;
  std::vector<std::thread> pool;
  pool.reserve(helpers);
  for (std::size_t t = 0; t < helpers; ++t)
    pool.emplace_back([&] {
      const double start = thread_cpu_seconds();
      work();
      std::lock_guard lock(mutex);
      helpers_cpu += thread_cpu_seconds() - start;
    });
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace

long add_point_stars(std::span<const SkyPoint> sky, int width, int height, const StarField& field,
                     const CameraDirections& camera, const StarPassOptions& options, std::span<float> rgb,
                     double* cpu_seconds) {
  const int w = width, h = height;
  const std::size_t pixels = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (w < 2 || h < 2 || sky.size() != pixels || rgb.size() != 3 * pixels)
    throw std::invalid_argument("star pass: the frame's rays or pixels do not match its size (at least 2 x 2)");
  const double start = thread_cpu_seconds();
  const Grid grid(sky, w, h);
  const double cos_max = std::cos(options.max_patch_radius);
  const double cos_wide = std::cos(wide_patch);
  const double cos_plane = std::cos(plane_tile);
  // Each row of tiles (tj = -1, -1 + tile, ...) on its own: its quads' areas,
  // its stars' images and the light they put on pixels, made without
  // reading another row's (the areas a row needs beyond its edge are made
  // again: the same numbers).  So the rows can run on any threads in any
  // order, and their deposits, joined in row order, are the one-thread
  // pass's to the bit.
  const int tile_rows = (h + 1 + tile - 1) / tile;
  std::vector<TileRow> rows(static_cast<std::size_t>(tile_rows));
  auto tile_row = [&](std::size_t row) {
    const int tj = -1 + static_cast<int>(row) * tile;
    // The camera's and the sky's solid angles of quad (i, j) (0 and 0 where
    // it is not used), made once each: the quads around one star's image
    // are those around its neighbours' in a crowded lensed ring.
    std::unordered_map<std::size_t, std::array<double, 2>> areas;
    auto quad_areas = [&](int i, int j) -> std::array<double, 2> {
      const std::size_t key = static_cast<std::size_t>(j + 1) * static_cast<std::size_t>(w + 1) + static_cast<std::size_t>(i + 1);
      if (const auto it = areas.find(key); it != areas.end()) return it->second;
      std::array<double, 2> a{0.0, 0.0};
      if (const auto q = make_quad(grid.at(i, j), grid.at(i + 1, j), grid.at(i + 1, j + 1), grid.at(i, j + 1), cos_max)) {
        const auto& k = q->corner;
        a = {SkyQuad{{camera(k[0].x, k[0].y), camera(k[1].x, k[1].y), camera(k[2].x, k[2].y), camera(k[3].x, k[3].y)}}
                 .area(),
             q->sky.area()};
      }
      return areas.emplace(key, a).first->second;
    };
    // The magnification at node (i, j): the camera's over the sky's solid
    // angle of the quads around it.
    auto magnification = [&](int i, int j) {
      double seen = 0.0, sky_area = 0.0;
      for (int qj = std::max(-1, j - 1); qj <= std::min(h - 1, j); ++qj)
        for (int qi = std::max(-1, i - 1); qi <= std::min(w - 1, i); ++qi) {
          const auto a = quad_areas(qi, qj);
          seen += a[0];
          sky_area += a[1];
        }
      return seen > 0.0 ? seen / std::max(sky_area, seen / options.max_magnification) : 0.0;
    };
    std::vector<Deposit> deposits;
    long images = 0;
    // An image of star s in quad q = (i, j): its light onto the pixels.
    auto draw = [&](int i, int j, const Quad& q, std::size_t s) {
      const auto uv = q.sky.locate(field.stars()[s].direction);
      // A star on an edge two quads share is counted in one: the one where
      // it is at u = 0 (v = 0).
      if (!uv || (*uv)[0] >= 1.0 - locate_slack || (*uv)[1] >= 1.0 - locate_slack) return;
      const double u = std::clamp((*uv)[0], 0.0, 1.0), v = std::clamp((*uv)[1], 0.0, 1.0);
      const double wt[4] = {(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v};
      const double mu[4] = {magnification(i, j), magnification(i + 1, j), magnification(i + 1, j + 1),
                            magnification(i, j + 1)};
      double m = 0.0, x = 0.0, y = 0.0, colour = 0.0, beaming = 0.0;
      for (std::size_t k = 0; k < 4; ++k) {
        m += wt[k] * mu[k];
        x += wt[k] * q.corner[k].x;
        y += wt[k] * q.corner[k].y;
        colour += wt[k] * q.corner[k].color;
        beaming += wt[k] * q.corner[k].beaming;
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
        Deposit d{pi_, pj, {}};
        for (int c = 0; c < 3; ++c) d.flux[c] = static_cast<float>(share * light[c]);
        deposits.push_back(d);
      }
      ++images;
    };
    // The images in quad (i, j) of the stars `each` offers (each(f) calls
    // f(star) for every one).  A star whose image here would be under a
    // thousandth of the faintest star's light is left out (the thin rings of
    // images at a shadow's edge hold most of a sky's stars, ever fainter):
    // twice the quad's own magnification bounds its corners'.
    auto stars_in = [&](int i, int j, const Quad& q, auto&& each) {
      const auto a = quad_areas(i, j);
      const double least =
          invisible * field.faintest_luminance() * std::max(a[1], a[0] / options.max_magnification) / (2.0 * a[0]);
      each([&](std::size_t s) {
        const Vec3& d = field.stars()[s].direction;
        if (field.luminance(s) >= least && dot3(d, q.centre) >= q.cos_reach && q.may_hold(d)) draw(i, j, q, s);
      });
    };
    // The quads of a tile of tile x tile (cut at the grid's end), made once;
    // a block of them is searched with one lookup in the bins for the cap
    // their patches span, and a block whose cap holds many stars (a patch of
    // sky the lens spreads wide) is split in four first, so each quad tests
    // few stars.
    std::vector<std::optional<Quad>> quads(static_cast<std::size_t>(tile * tile));
    // `from`: the stars the enclosing block found (none for a whole tile,
    // which asks the bins): a block only narrows them down.
    auto search = [&](auto&& self, int ti, int tj, int i0, int j0, int i1, int j1,
                      const std::vector<std::size_t>* from) -> void {
      auto quad = [&](int i, int j) -> const std::optional<Quad>& {
        return quads[static_cast<std::size_t>((j - tj) * tile + (i - ti))];
      };
      Vec3 sum{0, 0, 0};
      int count = 0;
      for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i)
          if (const auto& q = quad(i, j)) {
            for (int m = 0; m < 3; ++m) sum[m] += q->centre[m];
            ++count;
          }
      if (count == 0 || norm3(sum) == 0.0) return;
      const Vec3 centre = unit3(sum);
      double radius = 0.0;
      for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i)
          if (const auto& q = quad(i, j))
            radius = std::max(radius, std::acos(std::clamp(dot3(q->centre, centre), -1.0, 1.0)) +
                                          std::acos(std::clamp(q->cos_reach, -1.0, 1.0)));
      radius = std::min(radius, pi);
      const double cos_radius = std::cos(radius);
      std::vector<std::size_t> candidates;
      auto take = [&](std::size_t s) {
        if (dot3(field.stars()[s].direction, centre) >= cos_radius) candidates.push_back(s);
      };
      if (from)
        for (const std::size_t s : *from) take(s);
      else
        field.bins().near(centre, radius, take);
      if (candidates.empty()) return;
      if (candidates.size() > split_above && count > 1) {
        const int im = (i0 + i1 + 1) / 2, jm = (j0 + j1 + 1) / 2;
        for (const auto& [a0, a1] : {std::pair{i0, im}, std::pair{im, i1}})
          for (const auto& [b0, b1] : {std::pair{j0, jm}, std::pair{jm, j1}})
            if (a0 < a1 && b0 < b1) self(self, ti, tj, a0, b0, a1, b1, &candidates);
        return;
      }
      for (int j = j0; j < j1; ++j)
        for (int i = i0; i < i1; ++i)
          if (const auto& q = quad(i, j)) stars_in(i, j, *q, [&](auto&& f) {
              for (const std::size_t s : candidates) f(s);
            });
    };
    // Quads (i, j) .. (i + 1, j + 1) for i in [-1, w), j in [tj, tj + tile), a
    // tile at a time.
    for (int ti = -1; ti < w; ti += tile) {
      const int i1 = std::min(w, ti + tile), j1 = std::min(h, tj + tile);
      // The tile's nodes, made from the rays once.
      const int nw = i1 - ti + 1;
      std::vector<Node> nodes(static_cast<std::size_t>(nw * (j1 - tj + 1)));
      for (int j = tj; j <= j1; ++j)
        for (int i = ti; i <= i1; ++i) nodes[static_cast<std::size_t>((j - tj) * nw + (i - ti))] = grid.at(i, j);
      auto node = [&](int i, int j) -> const Node& { return nodes[static_cast<std::size_t>((j - tj) * nw + (i - ti))]; };
      // Most tiles see a small, smooth piece of sky: one lookup for the cap
      // their nodes span, then in the plane tangent to it (gnomonic) each
      // quad's box of corners holds few of the stars found, and only those
      // are tested exactly.
      Vec3 sum{0, 0, 0};
      int known = 0;
      for (const Node& n : nodes)
        if (n.known) {
          for (int m = 0; m < 3; ++m) sum[m] += n.sky[m];
          ++known;
        }
      if (known < 4) continue;
      if (norm3(sum) > 0.0) {
        const Vec3 centre = unit3(sum);
        double least = 1.0;
        for (const Node& n : nodes)
          if (n.known) least = std::min(least, dot3(n.sky, centre));
        if (least >= cos_plane) {
          std::vector<std::size_t> found;
          field.bins().near(centre, std::acos(least), [&](std::size_t s) {
            if (dot3(field.stars()[s].direction, centre) >= least) found.push_back(s);
          });
          if (found.empty()) continue;
          const Vec3 e1 = unit3(cross(centre, std::abs(centre[2]) < 0.9 ? Vec3{0, 0, 1} : Vec3{1, 0, 0}));
          const Vec3 e2 = cross(centre, e1);
          auto project = [&](const Vec3& v) {
            const double h = dot3(v, centre);
            return std::array<double, 2>{dot3(v, e1) / h, dot3(v, e2) / h};
          };
          std::vector<std::array<double, 2>> flat(nodes.size());
          for (std::size_t k = 0; k < nodes.size(); ++k)
            if (nodes[k].known) flat[k] = project(nodes[k].sky);
          // The stars found, by their x in the plane.
          struct Placed {
            double x, y;
            std::size_t star;
          };
          std::vector<Placed> at;
          at.reserve(found.size());
          for (const std::size_t s : found) {
            const auto p = project(field.stars()[s].direction);
            at.push_back({p[0], p[1], s});
          }
          std::sort(at.begin(), at.end(), [](const Placed& a, const Placed& b) { return a.x < b.x; });
          auto flat_at = [&](int i, int j) -> const std::array<double, 2>& {
            return flat[static_cast<std::size_t>((j - tj) * nw + (i - ti))];
          };
          std::vector<std::size_t> here;
          for (int j = tj; j < j1; ++j)
            for (int i = ti; i < i1; ++i) {
              if (!node(i, j).known || !node(i + 1, j).known || !node(i + 1, j + 1).known || !node(i, j + 1).known)
                continue;
              const auto &a = flat_at(i, j), &b = flat_at(i + 1, j), &c = flat_at(i + 1, j + 1), &d = flat_at(i, j + 1);
              // The box, a hair wider: locate decides on its edge.
              const double x0 = std::min({a[0], b[0], c[0], d[0]}), x1 = std::max({a[0], b[0], c[0], d[0]});
              const double y0 = std::min({a[1], b[1], c[1], d[1]}), y1 = std::max({a[1], b[1], c[1], d[1]});
              const double slack = 1e-9 * (x1 - x0 + y1 - y0) + 1e-15;
              here.clear();
              auto k = std::lower_bound(at.begin(), at.end(), x0 - slack,
                                        [](const Placed& p, double x) { return p.x < x; });
              for (; k != at.end() && k->x <= x1 + slack; ++k)
                if (k->y >= y0 - slack && k->y <= y1 + slack) here.push_back(k->star);
              if (here.empty()) continue;
              const auto q = make_quad(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1), cos_max);
              if (q) stars_in(i, j, *q, [&](auto&& f) {
                  for (const std::size_t s : here) f(s);
                });
            }
          continue;
        }
      }
      // A tile across a jump of the rays (a shadow's edge, where the lens
      // spreads neighbouring rays over the sky): its quads one by one.
      for (int j = tj; j < j1; ++j)
        for (int i = ti; i < i1; ++i)
          quads[static_cast<std::size_t>((j - tj) * tile + (i - ti))] =
              make_quad(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1), cos_max);
      // A wide patch (the lens spreads it over more than a bin) asks the
      // bins alone, so that the blocks' caps stay as small as their
      // patches are.
      for (int j = tj; j < j1; ++j)
        for (int i = ti; i < i1; ++i) {
          auto& q = quads[static_cast<std::size_t>((j - tj) * tile + (i - ti))];
          if (!q || q->cos_reach >= cos_wide) continue;
          stars_in(i, j, *q, [&](auto&& f) { field.bins().near(q->centre, std::acos(q->cos_reach), f); });
          q.reset();
        }
      search(search, ti, tj, ti, tj, i1, j1, nullptr);
    }
    rows[row] = {std::move(deposits), images};
  };
  double cpu = 0.0;
  for_each_parallel(rows.size(), options.threads, tile_row, cpu);
  std::vector<Deposit> deposits;
  long images = 0;
  for (TileRow& r : rows) {
    deposits.insert(deposits.end(), r.deposits.begin(), r.deposits.end());
    images += r.images;
  }
  // The light landed on each pixel, summed (a crowded lensed ring puts
  // many images on one).
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
  // Flux to radiance over each pixel's solid angle; the glare's share
  // spread over the halo around it (the pixels there taken as the same
  // size: the halo spans a few pixels).  Each lit pixel's radiance and halo
  // on its own, in parallel.
  const std::optional<GlareKernel> kernel =
      options.glare > 0.0 ? std::optional<GlareKernel>(GlareKernel(options.glare_radius)) : std::nullopt;
  std::vector<Lit> lit(deposits.size());
  constexpr std::size_t chunk = 256;
  for_each_parallel((deposits.size() + chunk - 1) / chunk, options.threads, [&](std::size_t c) {
    for (std::size_t k = c * chunk; k < std::min(deposits.size(), (c + 1) * chunk); ++k) {
      const Deposit& d = deposits[k];
      const double omega =
          SkyQuad{{camera(d.i, d.j), camera(d.i + 1, d.j), camera(d.i + 1, d.j + 1), camera(d.i, d.j + 1)}}.area();
      Lit& l = lit[k];
      for (int m = 0; m < 3; ++m) l.radiance[m] = static_cast<float>(d.flux[m] / omega);
      if (!kernel) continue;
      // The halo as far as it is brighter than the invisible share of the
      // faintest star's light on one pixel (a faint image's stops at once),
      // its weights scaled up to keep the light.
      const double glow = options.glare * (0.2126 * l.radiance[0] + 0.7152 * l.radiance[1] + 0.0722 * l.radiance[2]);
      const double floor = invisible * field.faintest_luminance() / omega;
      while (l.reach < kernel->radius && glow * kernel->at_radius[static_cast<std::size_t>(l.reach + 1)] >= floor) ++l.reach;
      l.share = options.glare / kernel->within[static_cast<std::size_t>(l.reach)];
    }
  }, cpu);
  // The light onto the image by bands of rows, each band from every lit
  // pixel whose halo reaches it, in the lit pixels' order: so each pixel
  // sums what lands on it in the order one thread would.
  const int reach = kernel ? kernel->radius : 0;
  const int bands = (h + tile - 1) / tile;
  for_each_parallel(static_cast<std::size_t>(bands), options.threads, [&](std::size_t b) {
    const int y0 = static_cast<int>(b) * tile, y1 = std::min(h, y0 + tile);
    auto row_at_least = [&](int j) {
      return std::partition_point(deposits.begin(), deposits.end(), [j](const Deposit& d) { return d.j < j; }) -
             deposits.begin();
    };
    const auto first = row_at_least(y0 - reach), last = row_at_least(y1 + reach);
    for (auto k = first; k < last; ++k) {
      const Deposit& d = deposits[static_cast<std::size_t>(k)];
      const Lit& l = lit[static_cast<std::size_t>(k)];
      auto add = [&](int i, int j, float weight) {
        float* p = &rgb[3 * (static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i))];
        for (int m = 0; m < 3; ++m) p[m] += weight * l.radiance[m];
      };
      if (!kernel) {
        if (d.j >= y0 && d.j < y1) add(d.i, d.j, 1.0f);
        continue;
      }
      if (d.j >= y0 && d.j < y1) add(d.i, d.j, static_cast<float>(1.0 - options.glare));
      const int r = l.reach, n = 2 * kernel->radius + 1, c0 = kernel->radius;
      for (int dy = std::max({-r, -d.j, y0 - d.j}); dy <= std::min({r, h - 1 - d.j, y1 - 1 - d.j}); ++dy)
        for (int dx = std::max(-r, -d.i); dx <= std::min(r, w - 1 - d.i); ++dx)
          if (const double k = kernel->weight[static_cast<std::size_t>((dy + c0) * n + dx + c0)]; k > 0.0)
            add(d.i + dx, d.j + dy, static_cast<float>(l.share * k));
    }
  }, cpu);
  if (cpu_seconds) *cpu_seconds += cpu + thread_cpu_seconds() - start;
  return images;
}

}  // namespace lc
