#include "render_command.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <thread>

#include <fmt/format.h>

#include "frame_files.hpp"
#include "frame_range.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "scene/shot.hpp"

namespace lc {

std::pair<int, int> output_size(int width, int height, const std::optional<std::string>& size, double scale) {
  if (size) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(size->c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
      throw std::invalid_argument(fmt::format("--size '{}': expected WxH, e.g. 1280x720", *size));
    width = w;
    height = h;
  }
  if (!(scale > 0.0) || !std::isfinite(scale))
    throw std::invalid_argument(fmt::format("--scale {}: must be a positive number", scale));
  width = static_cast<int>(std::lround(width * scale));
  height = static_cast<int>(std::lround(height * scale));
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw std::invalid_argument(fmt::format("image size {}x{} is out of range (1 to 16384 a side; check --size and --scale)",
                                            width, height));
  return {width, height};
}

int run_render(const RenderCommand& cmd) {
  Shot shot(cmd.shot);
  const ShotInfo& info = shot.info();
  const FrameRange range = cmd.frames ? parse_frame_range(*cmd.frames, info.frames, "--frames") : all_frames(info.frames);
  RenderSettings rs;
  std::tie(rs.width, rs.height) = output_size(info.width, info.height, cmd.size, cmd.scale);
  rs.supersample = cmd.supersample.value_or(info.supersample);
  if (rs.supersample < 1 || rs.supersample > 16)
    throw std::invalid_argument(fmt::format("--supersample {}: must be between 1 and 16", rs.supersample));
  rs.layers = cmd.layers;
  const int threads = cmd.threads > 0 ? cmd.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  std::error_code ec;
  std::filesystem::create_directories(cmd.out, ec);
  if (ec || !std::filesystem::is_directory(cmd.out))
    throw std::runtime_error(fmt::format("--out {}: cannot create the output directory: {}", cmd.out.string(),
                                         ec ? ec.message() : "a file of that name exists"));

  ShotResources resources(shot.asset_dirs());
  const auto frames = range.frames();
  fmt::print(stderr, "render: {} frame{} of '{}' at {}x{}, {}x{} samples per pixel, {} thread{} -> {}\n",
             frames.size(), frames.size() == 1 ? "" : "s", info.name, rs.width, rs.height, rs.supersample,
             rs.supersample, threads, threads == 1 ? "" : "s", cmd.out.string());
  const auto t_start = std::chrono::steady_clock::now();
  RenderStats total;
  int done = 0;
  for (int f : frames) {
    const auto t0 = std::chrono::steady_clock::now();
    const FrameScene fs = shot.frame(f);
    const Scene scene = [&] {
      try {
        return build_scene(fs, rs.width, rs.height, resources);
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(fmt::format("{}: frame {}: {}", cmd.shot.string(), f, e.what()));
      }
    }();
    RenderStats stats;
    const FrameImage img = render_frame(scene, rs, threads, &stats);
    write_frame_files(cmd.out, info.name, f, img,
                      {{"lightcone/shot", info.name},
                       {"lightcone/frame", std::to_string(f)},
                       {"lightcone/spacetime", describe(fs.spacetime)},
                       {"lightcone/supersample", std::to_string(rs.supersample)},
                       {"lightcone/version", LIGHTCONE_VERSION}});
    total += stats;
    ++done;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    fmt::print(stderr, "render: frame {} ({}/{}) in {:.2f} s, {} rays, {:.0f} rays/s{}\n", f, done, frames.size(), s,
               stats.rays, stats.rays / s,
               stats.gave_up ? fmt::format(", {} rays gave up (black)", stats.gave_up) : "");
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
  fmt::print(stderr, "render: done: {} frames in {:.2f} s, {} rays, {:.0f} rays per core-second\n", done, s, total.rays,
             total.rays / s / threads);
  return 0;
}

}  // namespace lc
