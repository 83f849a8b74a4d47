#include "render/renderer.hpp"

#include <algorithm>
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

template <class S>
RenderStats render_rows_of(const SceneOf<S>& sc, const RenderSettings& rs, std::span<const int> rows,
                           FrameImage& img) {
  RenderStats stats;
  const int N = rs.supersample;
  const bool centre_is_sample = N % 2 == 1;
  for (int j : rows) {
    for (int i = 0; i < rs.width; ++i) {
      double acc[3] = {0, 0, 0};
      RaySample centre;
      for (int b = 0; b < N; ++b)
        for (int a = 0; a < N; ++a) {
          const double px = i + (a + 0.5) / N, py = j + (b + 0.5) / N;
          const RaySample s = trace_sample(sc, sc.camera.direction(px, py), NoPath{});
          ++stats.rays;
          stats.steps += s.steps;
          if (s.kind == HitKind::gave_up) ++stats.gave_up;
          for (int c = 0; c < 3; ++c) acc[c] += s.color[c];
          if (centre_is_sample && a == N / 2 && b == N / 2) centre = s;
        }
      const std::size_t p = static_cast<std::size_t>(j) * rs.width + i;
      for (int c = 0; c < 3; ++c) img.rgb[3 * p + c] = static_cast<float>(acc[c] / (N * N));
      if (rs.layers) {
        if (!centre_is_sample) {
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
