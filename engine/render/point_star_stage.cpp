#include "render/point_star_stage.hpp"

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
  options.glare = stars.glare;
  options.glare_radius = stars.glare_size * image.height;
  options.threads = threads;
  options.wrap = camera.wrap();
  const long drawn = add_point_stars(rays, image.width, image.height, *stars.field,
                                     [&](double x, double y) { return unit3(camera.direction(x, y)); }, options,
                                     image.rgb, cpu_seconds);
  if (!camera.rays_everywhere()) black_outside_rays(camera, image);
  return drawn;
}

}  // namespace lc
