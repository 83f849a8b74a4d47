#include "render/renderer.hpp"

#include "core/parallel_for.hpp"
#include "render/layers.hpp"
#include "render/pixel_rows.hpp"
#include "render/scene_visit.hpp"

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
  img.alpha.assign(n, 1.0f);
  if (rs.layers)
    for (const LayerSpec& l : layers) img.layers.push_back({std::string(l.name), std::vector<float>(n, 0.0f)});
  return img;
}

void prepare_frame(const Scene& scene, FrameImage& image) {
  const bool stars = visit_scene([](const auto& sc) { return sc.sky.point_stars() != nullptr; }, scene);
  // A plane per instant of a blurred frame's shutter (docs/motion_blur.md).
  const std::size_t planes = visit_scene([](const auto& sc) { return std::max<std::size_t>(1, sc.instants.size()); }, scene);
  const std::size_t n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * planes;
  if (stars && image.sky.size() != n) image.sky.assign(n, SkyPoint{});
}

RenderStats render_rows(const Scene& scene, const RenderSettings& rs, std::span<const int> rows, FrameImage& image,
                        SampleMemo* memo) {
  return visit_scene([&](const auto& sc) { return render_rows_with(sc, sc.camera, rs, rows, image, memo); }, scene);
}

RaySample trace_image_point(const Scene& scene, double px, double py) {
  return visit_scene([&](const auto& sc) { return trace_sample(sc, sc.camera.direction(px, py)); }, scene);
}

FrameImage render_frame(const Scene& scene, const RenderSettings& rs, int threads, RenderStats* stats,
                        std::atomic<int>* rows_done) {
  FrameImage img = make_frame(rs);
  prepare_frame(scene, img);
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const std::size_t rows = static_cast<std::size_t>(std::max(rs.height, 0));
  std::vector<RenderStats> per_thread(parallel_workers(rows, threads));
  parallel_for(rows, {.threads = threads}, [&](std::size_t j, std::size_t worker) {
    const int row[1] = {static_cast<int>(j)};
    per_thread[worker] += render_rows(scene, rs, row, img);
    if (rows_done) rows_done->fetch_add(1);
  });
  if (stats)
    for (const auto& s : per_thread) *stats += s;
  return img;
}

}  // namespace lc
