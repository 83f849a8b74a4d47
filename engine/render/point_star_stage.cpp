#include "render/point_star_stage.hpp"

#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "stars/star_pass.hpp"

namespace lc {

namespace {

// Black where the camera has no ray through any part of a pixel (its
// centre and its four corners: a fisheye's pixels wholly outside its
// disc): the star stage's glare may spill there, but a dome shows nothing
// outside its disc.  The traced colour there is black already (no sample
// had a ray), so only star light is removed.
void black_outside_rays(const Camera& camera, FrameImage& image) {
  for (int j = 0; j < image.height; ++j)
    for (int i = 0; i < image.width; ++i) {
      if (camera.ray({i + 0.5, j + 0.5, 0.0})) continue;
      bool any = false;
      for (int c = 0; c < 4 && !any; ++c) any = camera.ray({i + (c & 1) * 1.0, j + (c >> 1) * 1.0, 0.0}).has_value();
      if (any) continue;
      const std::size_t p = 3 * (static_cast<std::size_t>(j) * image.width + i);
      image.rgb[p] = image.rgb[p + 1] = image.rgb[p + 2] = 0.0f;
    }
}

}  // namespace

long draw_point_stars(const PointStars& stars, const Camera& camera, std::span<const SkyPoint> rays,
                      FrameImage& image, int threads, double* cpu_seconds) {
  StarPassOptions options;
  options.threads = threads;
  options.wrap = camera.wrap();
  options.glare = stars.glare;
  const auto directions = [&](double x, double y) { return unit3(camera.direction(x, y)); };
  const std::vector<EyePicture> pictures = camera.pictures();
  long drawn = 0;
  if (pictures.size() == 1) {
    options.glare_radius = stars.glare_size * camera.frame_height();
    drawn = add_point_stars(rays, image.width, image.height, *stars.field, directions, options, image.rgb, cpu_seconds);
  } else {
    // A stereo frame: each eye's picture is a frame of its own to the
    // pass (its edges, its wrap), drawn on a copy of its pixels.
    for (const EyePicture& p : pictures) {
      const std::size_t w = static_cast<std::size_t>(p.width), n = w * static_cast<std::size_t>(p.height);
      std::vector<SkyPoint> sky(n);
      std::vector<float> rgb(3 * n);
      auto pixel = [&](std::size_t i, std::size_t j) {
        return (static_cast<std::size_t>(p.y0) + j) * static_cast<std::size_t>(image.width) + p.x0 + i;
      };
      for (std::size_t j = 0; j < static_cast<std::size_t>(p.height); ++j)
        for (std::size_t i = 0; i < w; ++i) {
          sky[j * w + i] = rays[pixel(i, j)];
          for (int c = 0; c < 3; ++c) rgb[3 * (j * w + i) + c] = image.rgb[3 * pixel(i, j) + c];
        }
      options.glare_radius = stars.glare_size * p.height;
      drawn += add_point_stars(sky, p.width, p.height, *stars.field, directions, options, rgb, cpu_seconds);
      for (std::size_t j = 0; j < static_cast<std::size_t>(p.height); ++j)
        for (std::size_t i = 0; i < w; ++i)
          for (int c = 0; c < 3; ++c) image.rgb[3 * pixel(i, j) + c] = rgb[3 * (j * w + i) + c];
    }
  }
  if (!camera.rays_everywhere()) black_outside_rays(camera, image);
  return drawn;
}

long draw_point_stars(std::span<const InstantStars> instants, std::span<const SkyPoint> rays, FrameImage& image,
                      int threads, double* cpu_seconds) {
  const std::size_t n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  if (rays.size() != n * instants.size())
    throw std::logic_error(fmt::format("the star stage got {} sky points for {} instants of {} pixels", rays.size(),
                                       instants.size(), n));
  const float weight = 1.0f / static_cast<float>(instants.size());
  FrameImage stars_only{image.width, image.height, {}, {}, {}, {}};
  long drawn = 0;
  for (std::size_t k = 0; k < instants.size(); ++k) {
    stars_only.rgb.assign(3 * n, 0.0f);
    drawn += draw_point_stars(*instants[k].stars, *instants[k].camera, rays.subspan(k * n, n), stars_only, threads,
                              cpu_seconds);
    for (std::size_t p = 0; p < 3 * n; ++p) image.rgb[p] += weight * stars_only.rgb[p];
  }
  return drawn;
}

}  // namespace lc
