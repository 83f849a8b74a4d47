#include "render/renderer.hpp"

#include "core/constants.hpp"

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

// The sample offsets of an N x N grid traced first when sampling
// adaptively: the corners (for N = 2 one diagonal), as (a, b) pairs.
std::vector<std::pair<int, int>> first_samples(int N) {
  if (N == 2) return {{0, 0}, {1, 1}};
  return {{0, 0}, {N - 1, 0}, {0, N - 1}, {N - 1, N - 1}};
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
  // rows of img (and layers), and the rays and steps spent.  Adaptive
  // sampling works along a row (the rows above and below belong to other
  // stripes): first the corner samples of every pixel, then the whole grid
  // of each pixel whose corners disagree with each other or with a
  // neighbour's in the row.
  RenderStats stats;
  const int N = rs.supersample;
  const bool centre_is_sample = N % 2 == 1;
  const bool adaptive = rs.adaptive && N >= 2;
  const std::vector<std::pair<int, int>> first = adaptive ? first_samples(N) : std::vector<std::pair<int, int>>{};
  const std::size_t F = first.size();
  auto trace = [&](int i, int j, int a, int b) {
    const double px = i + (a + 0.5) / N, py = j + (b + 0.5) / N;
    const RaySample s = trace_sample(sc, sc.camera.direction(px, py), NoPath{});
    ++stats.rays;
    stats.steps += s.steps;
    if (s.kind == HitKind::gave_up) ++stats.gave_up;
    return s;
  };
  std::vector<RaySample> firsts(F * static_cast<std::size_t>(rs.width));
  std::vector<char> refine(static_cast<std::size_t>(rs.width));
  for (int j : rows) {
    if (adaptive) {
      for (int i = 0; i < rs.width; ++i)
        for (std::size_t k = 0; k < F; ++k) firsts[i * F + k] = trace(i, j, first[k].first, first[k].second);
      for (int i = 0; i < rs.width; ++i) {
        bool r = false;
        for (std::size_t k = 1; k < F && !r; ++k) r = !samples_agree(firsts[i * F], firsts[i * F + k]);
        if (i > 0 && !r) r = !samples_agree(firsts[i * F], firsts[(i - 1) * F]);
        if (i + 1 < rs.width && !r) r = !samples_agree(firsts[i * F], firsts[(i + 1) * F]);
        refine[i] = r;
      }
    }
    for (int i = 0; i < rs.width; ++i) {
      double acc[3] = {0, 0, 0};
      int count = 0;
      RaySample centre;
      bool have_centre = false;
      auto add = [&](const RaySample& s, int a, int b) {
        for (int c = 0; c < 3; ++c) acc[c] += s.color[c];
        ++count;
        if (centre_is_sample && a == N / 2 && b == N / 2) {
          centre = s;
          have_centre = true;
        }
      };
      auto is_first = [&](int a, int b) {
        for (const auto& q : first)
          if (q.first == a && q.second == b) return true;
        return false;
      };
      for (std::size_t k = 0; k < F; ++k) add(firsts[i * F + k], first[k].first, first[k].second);
      if (!adaptive || refine[i])
        for (int b = 0; b < N; ++b)
          for (int a = 0; a < N; ++a)
            if (!is_first(a, b)) add(trace(i, j, a, b), a, b);
      const std::size_t p = static_cast<std::size_t>(j) * rs.width + i;
      for (int c = 0; c < 3; ++c) img.rgb[3 * p + c] = static_cast<float>(acc[c] / count);
      if (rs.layers) {
        if (!have_centre) {
          centre = trace_sample(sc, sc.camera.direction(i + 0.5, j + 0.5), NoPath{});
          ++stats.rays;
          stats.steps += centre.steps;
        }
        img.layers[0].values[p] = static_cast<float>(static_cast<int>(centre.kind));
        img.layers[1].values[p] = static_cast<float>(centre.r);
        img.layers[2].values[p] = static_cast<float>(centre.phi);
        img.layers[3].values[p] = static_cast<float>(centre.t);
        img.layers[4].values[p] = static_cast<float>(centre.order);
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
