#pragma once
// The renderer's stages for rows of pixels, each with one job, in the order
// a sample flows through them:
//   plan         which samples of the row's N x N pixel grids to take
//                (RowPlan: every one, or adaptive rounds);
//   generate     camera samples -> camera rays -> ray starts (generate_starts;
//                an image point without a ray is never traced);
//   trace        ray starts -> hit records (render/trace.hpp);
//   shade        hit records -> colours (render/shade.hpp), kept as the
//                frame uses them (FrameSample), with the sample memo's
//                kept samples standing in for traced ones;
//   reconstruct  samples -> pixels: colour, alpha (the share of samples with
//                a ray), the layers from the pixel's centre ray, the sky
//                point of its first ray (reconstruct_row).
// Where the frame's shutter is open and its scene changes within it
// (SceneIn::instants), each sample is at one instant of it
// (render/sample_times.hpp) and is generated, traced and shaded in that
// instant's scene.
// Templated on the camera so that any class satisfying CameraModel (a
// registered one, through Camera, or a test's own) drives the same stages.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "camera/camera_sample.hpp"
#include "core/constants.hpp"
#include "image/srgb.hpp"
#include "render/layers.hpp"
#include "render/ray_start.hpp"
#include "render/renderer.hpp"
#include "render/sample_memo.hpp"
#include "render/sample_times.hpp"
#include "render/shade.hpp"
#include "render/trace.hpp"

namespace lc {

namespace pixel_rows {

// Where the samples of a row sit: sample k = b N + a of pixel i's N x N grid
// is number i N N + k of the row; the layers' centre ray of pixel i (where
// no grid sample sits at the centre) is W N N + i.
struct RowGrid {
  int N;
  std::size_t W, NN;
  int centre;  // grid index b N + a of the centre sample, if N is odd; else -1
  RowGrid(int n, int width)
      : N(n), W(static_cast<std::size_t>(width)), NN(static_cast<std::size_t>(n) * n),
        centre(n % 2 == 1 ? (n / 2) * n + n / 2 : -1) {}
  // The sub-pixel (a, b) traced first in pixel column i when sampling
  // adaptively: one corner, alternating along the row between the top-left
  // and the bottom-right: neighbours' first samples then sit on different
  // sub-rows, so an edge that runs along the row inside a pixel row makes
  // them differ (a vertical one does anyway).
  std::pair<int, int> first_sample(std::size_t i) const {
    return i % 2 == 0 ? std::pair{0, 0} : std::pair{N - 1, N - 1};
  }
  std::size_t first_index(std::size_t i) const {
    const auto [a, b] = first_sample(i);
    return static_cast<std::size_t>(b) * N + a;
  }
  // The image point of sample g of row j.
  CameraSample point(std::size_t g, int j) const {
    const std::size_t i = g / NN, k = g % NN;
    const int a = static_cast<int>(k) % N, b = static_cast<int>(k) / N;
    return {static_cast<double>(i) + (a + 0.5) / N, j + (b + 0.5) / N, 0.0};
  }
};

// The instants of a row's grid samples in a frame whose shutter is open
// (sample_instants: the same for any split of the frame into rows and
// windows), and where each instant's sky points go.
struct RowTimes {
  std::vector<int> instant;  // of row sample g < W N N
  std::size_t plane = 0;     // pixels of the image: FrameImage::sky holds a plane of them per instant
  RowTimes(const RowGrid& grid, int instants, int j, const ImageWindow& window, std::size_t pixels)
      : instant(grid.W * grid.NN), plane(pixels) {
    for (std::size_t i = 0; i < grid.W; ++i)
      sample_instants(window.x0 + static_cast<std::int64_t>(i), window.y0 + static_cast<std::int64_t>(j), instants,
                      static_cast<int>(grid.first_index(i)), grid.first_sample(i).first != 0,
                      std::span<int>(instant.data() + i * grid.NN, grid.NN));
  }
  int of_first(const RowGrid& grid, std::size_t i) const { return instant[i * grid.NN + grid.first_index(i)]; }
};

// A sample as adaptive sampling compares it: its hit kind and its colour
// after the sRGB curve (what a viewer sees), worked out once per sample,
// not per comparison (the curve's pow shows in a Kerr frame's time:
// docs/performance.md, change 24).
struct Perceived {
  HitKind kind = HitKind::sky;
  std::array<double, 3> srgb{};
  explicit Perceived(const FrameSample& s) : kind(s.kind) {
    for (int c = 0; c < 3; ++c) srgb[c] = linear_to_srgb(s.color[c]);
  }
  Perceived() = default;
};

// Whether two samples agree closely enough to stand for the pixels and
// sub-pixels between them: the same hit kind, and every colour channel
// within adaptive_sample_threshold after the sRGB curve.
inline bool samples_agree(const Perceived& x, const Perceived& y) {
  if (x.kind != y.kind) return false;
  for (int c = 0; c < 3; ++c)
    if (std::abs(x.srgb[c] - y.srgb[c]) > adaptive_sample_threshold) return false;
  return true;
}

// The plan stage: which grid samples of a row to take, round by round.
// Not adaptive: every sample, in one round.  Adaptive (N >= 2, along the
// row: the rows above and below belong to other stripes): first one sample
// of every pixel (RowGrid::first_sample); then the whole grid of each pixel
// whose first sample disagrees with a row neighbour's; then, in rounds, of
// each neighbour of a pixel whose grid turned out not to be flat (a feature
// found inside one pixel may reach into the next without touching its
// first sample).  In a row that wraps around (a whole sphere's: `wraps`)
// the first and last pixels are neighbours.
class RowPlan {
 public:
  RowPlan(const RowGrid& grid, bool adaptive, bool wraps = false)
      : grid_(grid), adaptive_(adaptive), wraps_(wraps && grid.W >= 3), seen_(adaptive ? grid.W * grid.NN : 0),
        full_(grid.W), next_(grid.W) {}

  // The first round's samples into `where`.
  void first_round(std::vector<std::size_t>& where) {
    where.clear();
    for (std::size_t i = 0; i < grid_.W; ++i) {
      full_[i] = !adaptive_;
      if (adaptive_)
        where.push_back(i * grid_.NN + grid_.first_index(i));
      else
        for (std::size_t k = 0; k < grid_.NN; ++k) where.push_back(i * grid_.NN + k);
    }
  }
  // Takes in the samples of the round just taken (`where`, their values in
  // `samples` at their grid indices) and puts the next round's into
  // `where`: false when there is none.
  bool next_round(std::vector<std::size_t>& where, const std::vector<FrameSample>& samples) {
    if (!adaptive_) return false;
    for (const std::size_t g : where) seen_[g] = Perceived(samples[g]);
    if (first_) {
      first_ = false;
      for (std::size_t i = 0; i < grid_.W; ++i)
        next_[i] = (i > 0 && !samples_agree(first_of(i), first_of(i - 1))) ||
                   (i + 1 < grid_.W && !samples_agree(first_of(i), first_of(i + 1)));
      if (wraps_) {
        const std::size_t last = grid_.W - 1;
        if (!samples_agree(first_of(0), first_of(last))) next_[0] = next_[last] = 1;
      }
    } else {
      std::fill(next_.begin(), next_.end(), 0);
      for (const std::size_t g : where) full_[g / grid_.NN] = 2;  // refined in this round
      for (std::size_t i = 0; i < grid_.W; ++i) {
        if (full_[i] != 2) continue;
        full_[i] = 1;
        bool flat = true;
        for (std::size_t k = 0; k < grid_.NN && flat; ++k) flat = samples_agree(seen_[i * grid_.NN + k], first_of(i));
        if (!flat) {
          if (i > 0) next_[i - 1] = 1;
          if (i + 1 < grid_.W) next_[i + 1] = 1;
          if (wraps_ && i == 0) next_[grid_.W - 1] = 1;
          if (wraps_ && i + 1 == grid_.W) next_[0] = 1;
        }
      }
    }
    where.clear();
    for (std::size_t i = 0; i < grid_.W; ++i)
      if (next_[i] && !full_[i])
        for (std::size_t k = 0; k < grid_.NN; ++k)
          if (k != grid_.first_index(i)) where.push_back(i * grid_.NN + k);
    return !where.empty();
  }
  // Whether pixel i's whole grid was taken (else only its first sample).
  bool full(std::size_t i) const { return full_[i] != 0; }
  // Whether a grid sample of pixel i sits at its centre and was taken.
  bool has_centre_sample(std::size_t i) const {
    return grid_.centre >= 0 && (full_[i] || grid_.first_index(i) == static_cast<std::size_t>(grid_.centre));
  }

 private:
  const Perceived& first_of(std::size_t i) const { return seen_[i * grid_.NN + grid_.first_index(i)]; }
  const RowGrid& grid_;
  bool adaptive_, wraps_;
  bool first_ = true;
  std::vector<Perceived> seen_;  // the samples taken, as samples_agree compares them
  std::vector<char> full_, next_;
};

// The generate stage: the camera's rays through the image points `points`
// into `starts` (eyes from `eyes`); has_ray[n] says whether points[n] has
// one (the others are never traced).
template <class S, class C>
void generate_starts(const SceneIn<S>& sc, const C& camera, std::span<const CameraSample> points, EyePool& eyes,
                     std::vector<RayStart>& starts, std::vector<char>& has_ray) {
  starts.clear();
  has_ray.assign(points.size(), 0);
  for (std::size_t n = 0; n < points.size(); ++n)
    if (const std::optional<CameraRay> r = camera.ray(points[n])) {
      starts.push_back(eyes.start(sc, *r));
      has_ray[n] = 1;
    }
}

// The trace stage as the pixel stages call it: the records of the rays
// `starts` (of row j's samples `which`, in order) into `out`.  TraceRays
// traces them; a test may stand in records kept from another render
// (PixelRows.RecordsShadeToTheSamePixels), which is what makes the
// records the one source of everything after the trace.
struct TraceRays {
  template <class S>
  void operator()(const SceneIn<S>& sc, int, std::span<const std::size_t>, std::span<const RayStart> starts,
                  std::span<HitRecord> out) const {
    trace_records(sc, starts, out);
  }
};

// Scratch space of one thread's rows, kept between them.
struct RowBuffers {
  std::vector<CameraSample> points;
  std::vector<RayStart> starts;
  std::vector<char> has_ray;
  std::vector<HitRecord> records;
  std::vector<RaySample> shaded;
  std::vector<std::size_t> where, tracing, with_ray;
  EyePool eyes;
};

// The trace and shade stages for the samples at row indices `where` (image
// points from `point(g)`): kept ones from the memo row `kept`, the others
// generated, traced and shaded into out[g], and kept for later frames.
// `window`: whether their rays work out for how long they stay valid
// (HitRecord::reuse_window; 0: not worked out).  With `sky_point(g)`, the
// sample's sky point goes with it into and out of the memo.
template <class S, class C, class Tracer, class Point, class SkyPointOf>
void take_samples(const SceneIn<S>& sc, const C& camera, const Tracer& tracer, int j, std::size_t width,
                  std::span<const std::size_t> where, Point&& point, SkyPointOf&& sky_point,
                  std::optional<SampleMemo::Row>& kept, float window, RowBuffers& b, std::vector<FrameSample>& out,
                  RenderStats& stats) {
  b.points.clear();
  b.tracing.clear();
  for (const std::size_t g : where) {
    if (kept && kept->has(g)) {
      out[g] = kept->get(g);
      if (const auto i = sky_point(g)) out[g].sky = kept->sky(*i);
      ++stats.reused;
    } else {
      b.tracing.push_back(g);
      b.points.push_back(point(g));
    }
  }
  b.eyes.clear();
  generate_starts(sc, camera, std::span<const CameraSample>(b.points), b.eyes, b.starts, b.has_ray);
  b.with_ray.clear();
  for (std::size_t n = 0; n < b.tracing.size(); ++n)
    if (b.has_ray[n]) b.with_ray.push_back(b.tracing[n]);
  b.records.assign(b.starts.size(), HitRecord{});
  for (HitRecord& r : b.records) r.reuse_window = window;
  tracer(sc, j, std::span<const std::size_t>(b.with_ray), std::span<const RayStart>(b.starts),
         std::span<HitRecord>(b.records));
  b.shaded.resize(b.tracing.size());
  for (std::size_t n = 0, traced = 0; n < b.tracing.size(); ++n) {
    RaySample& s = b.shaded[n];
    if (b.has_ray[n]) {
      static_cast<HitRecord&>(s) = b.records[traced++];
      shade(sc, s);
      ++stats.rays;
      stats.steps += s.steps;
      if (s.kind == HitKind::gave_up) ++stats.gave_up;
    } else {
      s = no_ray_sample();
    }
    const std::size_t g = b.tracing[n];
    out[g] = frame_sample(s);
    if (kept) {
      kept->put(g, out[g], s.reuse_window);
      if (const auto i = sky_point(g)) kept->put_sky(*i, out[g].sky, width);
    }
  }
}

// The reconstruct stage: row j's pixels from its samples.  Colour: the mean
// of the samples taken (the whole grid, or the first sample of an
// unrefined pixel); alpha (where the image has it): the share of them with
// a ray; the layers: the centre sample's (in a blurred frame, `times`, the
// centre ray at the frame's own moment); the sky point: the first
// sample's, with where in the pixel it passed (in its instant's plane).
inline void reconstruct_row(const RowGrid& grid, const RowPlan& plan, const std::vector<FrameSample>& samples, int j,
                            bool layers, FrameImage& img, const RowTimes* times = nullptr) {
  const std::size_t W = grid.W, NN = grid.NN;
  for (std::size_t i = 0; i < W; ++i) {
    double acc[3] = {0, 0, 0};
    int n = 0, with_ray = 0;
    for (std::size_t k = 0; k < NN; ++k) {
      if (!plan.full(i) && k != grid.first_index(i)) continue;
      const FrameSample& s = samples[i * NN + k];
      for (int c = 0; c < 3; ++c) acc[c] += s.color[c];
      ++n;
      with_ray += s.kind != HitKind::no_ray;
    }
    const std::size_t p = static_cast<std::size_t>(j) * W + i;
    for (int c = 0; c < 3; ++c) img.rgb[3 * p + c] = static_cast<float>(acc[c] / n);
    if (!img.alpha.empty()) img.alpha[p] = static_cast<float>(with_ray) / static_cast<float>(n);
    if (!img.sky.empty()) {
      const auto [a, b] = grid.first_sample(i);
      SkyPoint& sp = img.sky[(times ? static_cast<std::size_t>(times->of_first(grid, i)) * times->plane : 0) + p];
      sp = samples[i * NN + grid.first_index(i)].sky;
      sp.dx = static_cast<float>((a + 0.5) / grid.N);
      sp.dy = static_cast<float>((b + 0.5) / grid.N);
    }
    if (layers) {
      const FrameSample& centre_sample = !times && plan.has_centre_sample(i)
                                             ? samples[i * NN + static_cast<std::size_t>(grid.centre)]
                                             : samples[W * NN + i];
      for (std::size_t l = 0; l < layer_count; ++l) img.layers[l].values[p] = centre_sample.layers[l];
    }
  }
}

}  // namespace pixel_rows

// Renders the listed rows of the scene sc as seen by `camera` into img (and
// its layers), and returns the rays and steps spent.  With a memo, samples
// kept from an earlier frame of the same still_key stand in for traced
// ones.  Each pixel's first sample is its ray for point stars (their grid:
// a fixed point of every pixel, traced whatever adaptive sampling does).
// `tracer` is the trace stage (pixel_rows::TraceRays).
//
// A blurred frame (sc.instants not empty: docs/motion_blur.md) takes a grid
// of at least as many samples as instants (samples_per_side), each in its
// instant's scene seen by that instant's camera; it neither takes nor
// keeps samples in the memo (its samples are not the frame's scene shifted
// in time); its layers are the centre ray's at the frame's own moment
// (sc, `camera`); and under point stars every instant gets a plane of sky
// points (a ray at each pixel's first-sample point: the instant's own
// sample where the pixel's first sample took it, else one more ray).
template <class S, class C, class Tracer = pixel_rows::TraceRays>
RenderStats render_rows_with(const SceneIn<S>& sc, const C& camera, const RenderSettings& rs, std::span<const int> rows,
                             FrameImage& img, SampleMemo* memo, const Tracer& tracer = {}) {
  using namespace pixel_rows;
  RenderStats stats;
  const int K = static_cast<int>(sc.instants.size());
  const bool blurred = K > 0;
  const RowGrid grid(blurred ? samples_per_side(rs.supersample, K) : rs.supersample, rs.width);
  const std::size_t W = grid.W, NN = grid.NN;
  const bool adaptive = rs.adaptive && grid.N >= 2;
  const bool sky_points = !img.sky.empty();
  if (blurred) memo = nullptr;
  RowBuffers buffers;
  // The row's samples by index (RowGrid), then (blurred, point stars) the
  // star grid's extra rays W N N + W + i.
  std::vector<FrameSample> samples(W * NN + 2 * W);
  std::vector<std::size_t> at_instant, extra;
  for (int j : rows) {
    std::optional<SampleMemo::Row> kept;
    if (memo) kept = memo->row(j, sc.still_key, sc.eye.time);
    // Rays work out how long they stay valid near a moving object only
    // where a later frame is likely to use it (0: not worked out).
    const float window = kept && kept->continues() ? std::numeric_limits<float>::infinity() : 0.0f;
    // Pixel i's first grid sample carries its sky point for point stars.
    auto grid_sky = [&](std::size_t g) -> std::optional<std::size_t> {
      if (sky_points && g % NN == grid.first_index(g / NN)) return g / NN;
      return std::nullopt;
    };
    std::optional<RowTimes> times;
    if (blurred) times.emplace(grid, K, j, rs.window, static_cast<std::size_t>(img.width) * img.height);
    // Image point `p` at instant `at`.
    auto at_moment = [](CameraSample p, const SceneIn<S>& at) {
      p.time = at.moment;
      return p;
    };
    // The samples `where` of the row, each in its instant's scene.
    auto take = [&](std::span<const std::size_t> where) {
      if (!blurred) {
        take_samples(sc, camera, tracer, j, W, where, [&](std::size_t g) { return grid.point(g, j); }, grid_sky, kept,
                     window, buffers, samples, stats);
        return;
      }
      for (int k = 0; k < K; ++k) {
        const SceneIn<S>& at = sc.instants[static_cast<std::size_t>(k)];
        at_instant.clear();
        for (const std::size_t g : where)
          if (times->instant[g] == k) at_instant.push_back(g);
        take_samples(
            at, at.camera, tracer, j, W, std::span<const std::size_t>(at_instant),
            [&](std::size_t g) { return at_moment(grid.point(g, j), at); }, grid_sky, kept, window, buffers, samples,
            stats);
      }
    };
    RowPlan plan(grid, adaptive, camera.wrap().columns);
    std::vector<std::size_t>& where = buffers.where;
    plan.first_round(where);
    do {
      take(std::span<const std::size_t>(where));
    } while (plan.next_round(where, samples));

    // The layers take the pixel-centre sample; it is traced where no grid
    // sample sits there (even N), it was not taken (an unrefined pixel) or
    // it is not at the frame's moment (a blurred frame).
    std::vector<std::size_t> centres;
    if (rs.layers)
      for (std::size_t i = 0; i < W; ++i)
        if (blurred || !plan.has_centre_sample(i)) centres.push_back(W * NN + i);
    take_samples(
        sc, camera, tracer, j, W, std::span<const std::size_t>(centres),
        [&](std::size_t g) { return CameraSample{static_cast<double>(g - W * NN) + 0.5, j + 0.5, 0.0}; },
        [](std::size_t) { return std::optional<std::size_t>{}; }, kept, window, buffers, samples, stats);

    reconstruct_row(grid, plan, samples, j, rs.layers, img, times ? &*times : nullptr);

    // A blurred frame's star grid: every instant's ray through each pixel's
    // first-sample point, into the instant's plane (the point-star stage
    // draws each instant's stars from its own).
    if (blurred && sky_points)
      for (int k = 0; k < K; ++k) {
        const SceneIn<S>& at = sc.instants[static_cast<std::size_t>(k)];
        extra.clear();
        for (std::size_t i = 0; i < W; ++i)
          if (times->of_first(grid, i) != k) extra.push_back(W * NN + W + i);
        auto first_point = [&](std::size_t g) {
          const std::size_t i = g - W * NN - W;
          return at_moment(grid.point(i * NN + grid.first_index(i), j), at);
        };
        std::optional<SampleMemo::Row> none;
        take_samples(at, at.camera, tracer, j, W, std::span<const std::size_t>(extra), first_point,
                     [](std::size_t) { return std::optional<std::size_t>{}; }, none, 0.0f, buffers, samples, stats);
        for (const std::size_t g : extra) {
          const std::size_t i = g - W * NN - W;
          const auto [a, b] = grid.first_sample(i);
          SkyPoint& sp = img.sky[static_cast<std::size_t>(k) * times->plane + static_cast<std::size_t>(j) * W + i];
          sp = samples[g].sky;
          sp.dx = static_cast<float>((a + 0.5) / grid.N);
          sp.dy = static_cast<float>((b + 0.5) / grid.N);
        }
      }
  }
  return stats;
}

}  // namespace lc
