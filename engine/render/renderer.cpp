#include "render/renderer.hpp"

#include "core/constants.hpp"
#include "image/srgb.hpp"
#include "render/layers.hpp"
#include "render/sample_memo.hpp"
#include "render/trace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <thread>
#include <vector>

namespace lc {

FrameImage make_frame(const RenderSettings& rs) {
  FrameImage img;
  img.width = rs.width;
  img.height = rs.height;
  const std::size_t n = static_cast<std::size_t>(rs.width) * rs.height;
  img.rgb.assign(3 * n, 0.0f);
  if (rs.layers)
    for (const LayerSpec& l : layers) img.layers.push_back({std::string(l.name), std::vector<float>(n, 0.0f)});
  return img;
}

void prepare_frame(const Scene& scene, FrameImage& image) {
  const bool stars = std::visit([](const auto& sc) { return sc.sky.point_stars() != nullptr; }, scene);
  const std::size_t n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  if (stars && image.sky.size() != n) image.sky.assign(n, SkyPoint{});
}

namespace {

// The sub-pixel (a, b) of an N x N grid traced first in pixel column i when
// sampling adaptively: one corner, alternating along the row between the
// top-left and the bottom-right: neighbours' first samples then sit on
// different sub-rows, so an edge that runs along the row inside a pixel row
// makes them differ (a vertical one does anyway).
std::pair<int, int> first_sample(int N, std::size_t i) { return i % 2 == 0 ? std::pair{0, 0} : std::pair{N - 1, N - 1}; }

// A traced sample as adaptive sampling compares it: its hit kind and its
// colour after the sRGB curve (what a viewer sees), worked out once per
// sample, not per comparison (the curve's pow shows in a Kerr frame's time:
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
bool samples_agree(const Perceived& x, const Perceived& y) {
  if (x.kind != y.kind) return false;
  for (int c = 0; c < 3; ++c)
    if (std::abs(x.srgb[c] - y.srgb[c]) > adaptive_sample_threshold) return false;
  return true;
}

template <class S>
RenderStats render_rows_of(const SceneIn<S>& sc, const RenderSettings& rs, std::span<const int> rows,
                           FrameImage& img, SampleMemo* memo) {
  // Inputs: a scene, the settings and the rows to render; output: those
  // rows of img (and layers), and the rays and steps spent.  A row's
  // samples are traced in batches (trace_batch: several rays at once where
  // the spacetime allows).  Adaptive sampling works along a row (the rows
  // above and below belong to other stripes): first one sample of every
  // pixel (first_sample); then the whole grid of each pixel whose first
  // sample disagrees with a row neighbour's; then, in rounds, of each
  // neighbour of a pixel whose grid turned out not to be flat (a feature
  // found inside one pixel may reach into the next without touching its
  // first sample).  With a memo, samples kept from an earlier frame of the
  // same still_key stand in for traced ones.
  RenderStats stats;
  const int N = rs.supersample;
  const std::size_t NN = static_cast<std::size_t>(N) * N;
  const bool adaptive = rs.adaptive && N >= 2;
  const int centre = N % 2 == 1 ? (N / 2) * N + N / 2 : -1;  // index b * N + a of the centre sample, if any
  const std::size_t W = static_cast<std::size_t>(rs.width);
  // Each pixel's first sample is its ray for point stars (their grid: a
  // fixed point of every pixel, traced whatever adaptive sampling does).
  const bool sky_points = !img.sky.empty();
  auto first_index = [&](std::size_t i) {
    const auto [a, b] = first_sample(N, i);
    return static_cast<std::size_t>(b) * N + a;
  };
  auto count = [&](std::span<const RaySample> samples) {
    for (const RaySample& s : samples) {
      ++stats.rays;
      stats.steps += s.steps;
      if (s.kind == HitKind::gave_up) ++stats.gave_up;
    }
  };
  auto dir = [&](std::size_t i, int j, std::size_t k) {
    const int a = static_cast<int>(k) % N, b = static_cast<int>(k) / N;
    return sc.camera.direction(static_cast<double>(i) + (a + 0.5) / N, j + (b + 0.5) / N);
  };
  std::vector<Vec3> dirs;
  std::vector<RaySample> traced;
  std::vector<std::size_t> where;   // grid index of each sample wanted
  std::vector<std::size_t> tracing;  // of those, the ones not kept in the memo
  std::vector<FrameSample> grid(W * NN);  // sample k = b * N + a of pixel i at i * NN + k
  std::vector<Perceived> seen(adaptive ? W * NN : 0);  // the same, as samples_agree compares them
  std::vector<char> full(W), next(W);
  std::vector<FrameSample> centres(rs.layers ? W : 0);  // pixel i's centre ray, where the layers need one
  for (int j : rows) {
    std::optional<SampleMemo::Row> kept;
    if (memo) kept = memo->row(j, sc.still_key, sc.observer_time);
    // Rays work out how long they stay valid near a moving object only
    // where a later frame is likely to use it (RayHit::reuse_window; 0 on
    // entry: not worked out, trace_rays).
    const float window = kept && kept->continues() ? std::numeric_limits<float>::infinity() : 0.0f;
    // Room for n traced samples, each told whether to work out its window
    // (trace_batch fills in the rest).
    auto make_room = [&](std::size_t n) {
      traced.resize(n);
      for (RaySample& s : traced) s.reuse_window = window;
    };
    // Fills the samples at grid indices `where` into the grid: kept ones
    // from the memo, the others traced (and kept for later frames).
    auto trace_row = [&]() {
      dirs.clear();
      tracing.clear();
      for (const std::size_t g : where) {
        if (kept && kept->has(g)) {
          grid[g] = kept->get(g);
          if (sky_points && g % NN == first_index(g / NN)) grid[g].sky = kept->sky(g / NN);
          ++stats.reused;
        } else {
          tracing.push_back(g);
          dirs.push_back(dir(g / NN, j, g % NN));
        }
      }
      make_room(dirs.size());
      trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(traced));
      count(traced);
      for (std::size_t n = 0; n < tracing.size(); ++n) {
        const std::size_t g = tracing[n];
        grid[g] = frame_sample(traced[n]);
        if (kept) {
          kept->put(g, grid[g], traced[n].reuse_window);
          if (sky_points && g % NN == first_index(g / NN)) kept->put_sky(g / NN, grid[g].sky, W);
        }
      }
      if (adaptive)
        for (const std::size_t g : where) seen[g] = Perceived(grid[g]);
    };
    // Every pixel's grid where not adaptive, else its first sample; then
    // the grids of the pixels marked in `next`, in rounds.
    where.clear();
    for (std::size_t i = 0; i < W; ++i) {
      full[i] = !adaptive;
      if (adaptive)
        where.push_back(i * NN + first_index(i));
      else
        for (std::size_t k = 0; k < NN; ++k) where.push_back(i * NN + k);
    }
    trace_row();
    auto first_of = [&](std::size_t i) -> const Perceived& { return seen[i * NN + first_index(i)]; };
    for (std::size_t i = 0; adaptive && i < W; ++i)
      next[i] = (i > 0 && !samples_agree(first_of(i), first_of(i - 1))) ||
                (i + 1 < W && !samples_agree(first_of(i), first_of(i + 1)));
    while (adaptive) {
      where.clear();
      for (std::size_t i = 0; i < W; ++i)
        if (next[i] && !full[i])
          for (std::size_t k = 0; k < NN; ++k)
            if (k != first_index(i)) where.push_back(i * NN + k);
      if (where.empty()) break;
      trace_row();
      std::fill(next.begin(), next.end(), 0);
      for (const std::size_t g : where) full[g / NN] = 2;  // refined in this round
      for (std::size_t i = 0; i < W; ++i) {
        if (full[i] != 2) continue;
        full[i] = 1;
        bool flat = true;
        for (std::size_t k = 0; k < NN && flat; ++k) flat = samples_agree(seen[i * NN + k], first_of(i));
        if (!flat) {
          if (i > 0) next[i - 1] = 1;
          if (i + 1 < W) next[i + 1] = 1;
        }
      }
    }

    // The layers take the pixel-centre sample; trace it where no sample sits
    // there (even N) or it was not traced (an unrefined pixel).  In the
    // memo it is sample W N N + i.
    auto has_centre_sample = [&](std::size_t i) {
      return centre >= 0 && (full[i] || first_index(i) == static_cast<std::size_t>(centre));
    };
    dirs.clear();
    tracing.clear();
    if (rs.layers)
      for (std::size_t i = 0; i < W; ++i) {
        if (has_centre_sample(i)) continue;
        if (kept && kept->has(W * NN + i)) {
          centres[i] = kept->get(W * NN + i);
          ++stats.reused;
        } else {
          tracing.push_back(i);
          dirs.push_back(sc.camera.direction(static_cast<double>(i) + 0.5, j + 0.5));
        }
      }
    make_room(dirs.size());
    trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(traced));
    count(traced);
    for (std::size_t n = 0; n < tracing.size(); ++n) {
      centres[tracing[n]] = frame_sample(traced[n]);
      if (kept) kept->put(W * NN + tracing[n], centres[tracing[n]], traced[n].reuse_window);
    }

    for (std::size_t i = 0; i < W; ++i) {
      double acc[3] = {0, 0, 0};
      int n = 0;
      for (std::size_t k = 0; k < NN; ++k) {
        if (!full[i] && k != first_index(i)) continue;
        for (int c = 0; c < 3; ++c) acc[c] += grid[i * NN + k].color[c];
        ++n;
      }
      const std::size_t p = static_cast<std::size_t>(j) * W + i;
      for (int c = 0; c < 3; ++c) img.rgb[3 * p + c] = static_cast<float>(acc[c] / n);
      if (sky_points) {
        const auto [a, b] = first_sample(N, i);
        SkyPoint& sp = img.sky[p];
        sp = grid[i * NN + first_index(i)].sky;
        sp.dx = static_cast<float>((a + 0.5) / N);
        sp.dy = static_cast<float>((b + 0.5) / N);
      }
      if (rs.layers) {
        const FrameSample& centre_sample =
            has_centre_sample(i) ? grid[i * NN + static_cast<std::size_t>(centre)] : centres[i];
        for (std::size_t l = 0; l < layer_count; ++l) img.layers[l].values[p] = centre_sample.layers[l];
      }
    }
  }
  return stats;
}

}  // namespace

RenderStats render_rows(const Scene& scene, const RenderSettings& rs, std::span<const int> rows, FrameImage& image,
                        SampleMemo* memo) {
  return std::visit([&](const auto& sc) { return render_rows_of(sc, rs, rows, image, memo); }, scene);
}

FrameImage render_frame(const Scene& scene, const RenderSettings& rs, int threads, RenderStats* stats,
                        std::atomic<int>* rows_done) {
  FrameImage img = make_frame(rs);
  prepare_frame(scene, img);
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = std::min(threads, rs.height);
  std::atomic<int> next{0};
  std::vector<RenderStats> per_thread(threads);
  auto worker = [&](int k) {
    for (int j; (j = next.fetch_add(1)) < rs.height;) {
      const int row[1] = {j};
      per_thread[k] += render_rows(scene, rs, row, img);
      if (rows_done) rows_done->fetch_add(1);
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker, k);
  worker(0);
  for (auto& t : pool) t.join();
  if (stats)
    for (const auto& s : per_thread) *stats += s;
  return img;
}

}  // namespace lc
