#include "render/renderer.hpp"

#include "core/constants.hpp"
#include "render/trace_batch.hpp"

#include <algorithm>
#include <cmath>
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
    for (const char* name : layer_names) img.layers.push_back({name, std::vector<float>(n, 0.0f)});
  return img;
}

namespace {

// The sample offsets (a, b) of an N x N grid traced first: with adaptive
// sampling the corners (for N = 2 one diagonal), else the whole grid in
// row order.
std::vector<std::pair<int, int>> first_samples(int N, bool adaptive) {
  if (adaptive && N == 2) return {{0, 0}, {1, 1}};
  if (adaptive) return {{0, 0}, {N - 1, 0}, {0, N - 1}, {N - 1, N - 1}};
  std::vector<std::pair<int, int>> all;
  for (int b = 0; b < N; ++b)
    for (int a = 0; a < N; ++a) all.push_back({a, b});
  return all;
}

// Whether two samples agree closely enough to stand for the pixels and
// sub-pixels between them.
bool samples_agree(const RaySample& x, const RaySample& y) {
  if (x.kind != y.kind) return false;
  for (int c = 0; c < 3; ++c)
    if (std::abs(x.color[c] - y.color[c]) > adaptive_sample_threshold) return false;
  return true;
}

template <class S>
RenderStats render_rows_of(const SceneOf<S>& sc, const RenderSettings& rs, std::span<const int> rows,
                           FrameImage& img) {
  // Inputs: a scene, the settings and the rows to render; output: those
  // rows of img (and layers), and the rays and steps spent.  A row's
  // samples are traced in batches (trace_batch: several rays at once where
  // the spacetime allows).  Adaptive sampling works along a row (the rows
  // above and below belong to other stripes): first the corner samples of
  // every pixel, then the whole grid of each pixel whose corners disagree
  // with each other or with a neighbour's in the row.
  RenderStats stats;
  const int N = rs.supersample;
  const bool adaptive = rs.adaptive && N >= 2;
  const std::vector<std::pair<int, int>> first = first_samples(N, adaptive);
  const std::size_t F = first.size();
  std::vector<char> is_first(static_cast<std::size_t>(N) * N, 0);
  for (const auto& [a, b] : first) is_first[static_cast<std::size_t>(b) * N + a] = 1;
  const int centre = N % 2 == 1 ? (N / 2) * N + N / 2 : -1;  // index of the centre sample, if there is one
  const std::size_t W = static_cast<std::size_t>(rs.width);
  auto count = [&](std::span<const RaySample> samples) {
    for (const RaySample& s : samples) {
      ++stats.rays;
      stats.steps += s.steps;
      if (s.kind == HitKind::gave_up) ++stats.gave_up;
    }
  };
  auto dir = [&](int i, int j, int a, int b) { return sc.camera.direction(i + (a + 0.5) / N, j + (b + 0.5) / N); };
  std::vector<Vec3> dirs;
  std::vector<RaySample> firsts, rest, centres;
  std::vector<char> refine(W);
  for (int j : rows) {
    dirs.clear();
    for (std::size_t i = 0; i < W; ++i)
      for (const auto& [a, b] : first) dirs.push_back(dir(static_cast<int>(i), j, a, b));
    firsts.resize(dirs.size());
    trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(firsts));
    count(firsts);

    dirs.clear();
    for (std::size_t i = 0; i < W; ++i) {
      bool r = false;
      if (adaptive) {
        for (std::size_t k = 1; k < F && !r; ++k) r = !samples_agree(firsts[i * F], firsts[i * F + k]);
        if (i > 0 && !r) r = !samples_agree(firsts[i * F], firsts[(i - 1) * F]);
        if (i + 1 < W && !r) r = !samples_agree(firsts[i * F], firsts[(i + 1) * F]);
      }
      refine[i] = r;
      if (r)
        for (int b = 0; b < N; ++b)
          for (int a = 0; a < N; ++a)
            if (!is_first[static_cast<std::size_t>(b) * N + a]) dirs.push_back(dir(static_cast<int>(i), j, a, b));
    }
    rest.resize(dirs.size());
    trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(rest));
    count(rest);

    // The layers take the pixel-centre sample; trace it where no sample sits
    // there (even N) or the centre was not traced (an unrefined odd grid).
    const bool centre_traced_always = centre >= 0 && is_first[static_cast<std::size_t>(centre)];
    dirs.clear();
    if (rs.layers)
      for (std::size_t i = 0; i < W; ++i)
        if (!centre_traced_always && !(centre >= 0 && refine[i]))
          dirs.push_back(sc.camera.direction(static_cast<double>(i) + 0.5, j + 0.5));
    centres.resize(dirs.size());
    trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(centres));
    count(centres);

    std::size_t next_rest = 0, next_centre = 0;
    for (std::size_t i = 0; i < W; ++i) {
      double acc[3] = {0, 0, 0};
      int n = 0;
      const RaySample* centre_sample = nullptr;
      for (std::size_t k = 0; k < F; ++k) {
        const RaySample& s = firsts[i * F + k];
        for (int c = 0; c < 3; ++c) acc[c] += s.color[c];
        ++n;
        if (first[k].second * N + first[k].first == centre) centre_sample = &s;
      }
      if (refine[i])
        for (int b = 0; b < N; ++b)
          for (int a = 0; a < N; ++a) {
            if (is_first[static_cast<std::size_t>(b) * N + a]) continue;
            const RaySample& s = rest[next_rest++];
            for (int c = 0; c < 3; ++c) acc[c] += s.color[c];
            ++n;
            if (b * N + a == centre) centre_sample = &s;
          }
      const std::size_t p = static_cast<std::size_t>(j) * W + i;
      for (int c = 0; c < 3; ++c) img.rgb[3 * p + c] = static_cast<float>(acc[c] / n);
      if (rs.layers) {
        if (!centre_sample) centre_sample = &centres[next_centre++];
        img.layers[0].values[p] = static_cast<float>(static_cast<int>(centre_sample->kind));
        img.layers[1].values[p] = static_cast<float>(centre_sample->r);
        img.layers[2].values[p] = static_cast<float>(centre_sample->phi);
        img.layers[3].values[p] = static_cast<float>(centre_sample->t);
        img.layers[4].values[p] = static_cast<float>(centre_sample->order);
      }
    }
  }
  return stats;
}

}  // namespace

RenderStats render_rows(const Scene& scene, const RenderSettings& rs, std::span<const int> rows, FrameImage& image) {
  return std::visit([&](const auto& sc) { return render_rows_of(sc, rs, rows, image); }, scene);
}

FrameImage render_frame(const Scene& scene, const RenderSettings& rs, int threads, RenderStats* stats,
                        std::atomic<int>* rows_done) {
  FrameImage img = make_frame(rs);
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
