#include "render/point_star_stage.hpp"

#include "stars/star_pass.hpp"

namespace lc {

long draw_point_stars(const PointStars& stars, const Camera& camera, std::span<const SkyPoint> rays,
                      FrameImage& image, int threads, double* cpu_seconds) {
  StarPassOptions options;
  options.glare = stars.glare;
  options.glare_radius = stars.glare_size * image.height;
  options.threads = threads;
  return add_point_stars(rays, image.width, image.height, *stars.field,
                         [&](double x, double y) { return unit3(camera.direction(x, y)); }, options, image.rgb,
                         cpu_seconds);
}

}  // namespace lc
