#include "render/point_star_stage.hpp"

#include "stars/star_pass.hpp"

namespace lc {

long draw_point_stars(const Sky& sky, const Camera& camera, std::span<const SkyPoint> rays, FrameImage& image) {
  const PointStars* stars = sky.point_stars();
  if (!stars || rays.empty()) return 0;
  StarPassOptions options;
  options.glare = stars->glare;
  options.glare_radius = stars->glare_size * image.height;
  return add_point_stars(rays, image.width, image.height, *stars->field,
                         [&](double x, double y) { return unit3(camera.direction(x, y)); }, options, image.rgb);
}

}  // namespace lc
