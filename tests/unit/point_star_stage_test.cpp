// Point stars through the pipeline's stage after the pixels (engine/render/
// point_star_stage.hpp) on frames the renderer made: in flat space, a slow
// pan of 100 frames (a tenth of a pixel each, 2 x 2 adaptive samples, whose
// first samples a quarter pixel off the centres carry the sky points) keeps
// each star's summed light within 2% (the no-flicker bound; the
// pass conserves it to ~1e-3 here) and within the 2 x 2 pixels around it.

#include "camera/pinhole_params.hpp"
#include "render/point_star_stage.hpp"
#include "spacetime/minkowski.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "core/constants.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "render/trace.hpp"
#include "stars/sky_quad.hpp"

namespace lc {
namespace {

TEST(PointStarStage, AStarsLightHoldsStillThroughASlowPan) {
  const int W = 64, H = 36;
  const double fov = 20, step = 0.1 * fov / W;  // a tenth of a pixel (near the centre), degrees
  SceneSpec fs;
  fs.spacetime = Minkowski{};
  fs.observer = StaticObserver::Params{{0, 0, 40, 0}};
  PointStarSky::Params sky;
  sky.background = "none";
  fs.sky = sky;
  RenderSettings rs{W, H, 2, false};
  ShotResources res;
  // Three stars where frame 0's rays through three image points went.
  std::vector<PointStar> stars;
  const double at[3][2] = {{20.3, 10.7}, {40.55, 18.2}, {30.9, 27.45}};
  {
    fs.camera.get<PinholeParams>().fov = fov;
    const Scene scene = build_scene(fs, W, H, res);
    const auto& sc = scene_get<Minkowski>(scene);
    std::vector<Vec3> dirs;
    for (const auto& p : at) dirs.push_back(sc.camera.direction(p[0], p[1]));
    std::vector<RaySample> out(dirs.size());
    trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(out));
    for (const RaySample& s : out) {
      ASSERT_TRUE(s.sky.reached());
      const double t = s.sky.theta, p = s.sky.phi;
      stars.push_back({{std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)}, {1, 1, 1}, 0.0});
    }
  }
  const PointStars points{std::make_shared<const StarField>(stars, nullptr, nullptr), 0.0, 0.0};
  double where[3][2] = {{at[0][0], at[0][1]}, {at[1][0], at[1][1]}, {at[2][0], at[2][1]}};
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {0, 0, 0};
  for (int f = 0; f < 100; ++f) {
    fs.camera.get<PinholeParams>().yaw = f * step;
    const Scene scene = build_scene(fs, W, H, res);
    FrameImage image = make_frame(rs);
    prepare_frame(scene, image);
    std::vector<int> rows(H);
    std::iota(rows.begin(), rows.end(), 0);
    render_rows(scene, rs, rows, image);
    ASSERT_EQ(image.sky.size(), static_cast<std::size_t>(W * H));
    const Camera camera(fs.camera, W, H);
    std::fill(image.rgb.begin(), image.rgb.end(), 0.0f);  // the stars' light alone
    EXPECT_EQ(draw_point_stars(points, camera, image.sky, image), 3) << "frame " << f;
    auto omega = [&](int i, int j) {
      return SkyQuad{{unit3(camera.direction(i, j)), unit3(camera.direction(i + 1, j)),
                      unit3(camera.direction(i + 1, j + 1)), unit3(camera.direction(i, j + 1))}}
          .area();
    };
    for (int s = 0; s < 3; ++s) {
      // The star's light in a 7 x 7 window around where it was: its sum,
      // its centroid and its extent.
      const int ci = static_cast<int>(where[s][0]), cj = static_cast<int>(where[s][1]);
      double sum = 0, x = 0, y = 0;
      int i0 = W, i1 = -1, j0 = H, j1 = -1;
      for (int j = cj - 3; j <= cj + 3; ++j)
        for (int i = ci - 3; i <= ci + 3; ++i) {
          const float r = image.rgb[3 * static_cast<std::size_t>(j * W + i)];
          if (r <= 0) continue;
          const double flux = r * omega(i, j);
          sum += flux;
          x += flux * (i + 0.5);
          y += flux * (j + 0.5);
          i0 = std::min(i0, i), i1 = std::max(i1, i), j0 = std::min(j0, j), j1 = std::max(j1, j);
        }
      ASSERT_GT(sum, 0) << "star " << s << " frame " << f;
      EXPECT_LE(i1 - i0, 1) << "star " << s << " frame " << f;
      EXPECT_LE(j1 - j0, 1) << "star " << s << " frame " << f;
      where[s][0] = x / sum;
      where[s][1] = y / sum;
      lo[s] = std::min(lo[s], sum), hi[s] = std::max(hi[s], sum);
    }
  }
  for (int s = 0; s < 3; ++s) {
    EXPECT_LT((hi[s] - lo[s]) / lo[s], 0.02) << "star " << s;
    // It moved ten pixels across.
    EXPECT_NEAR(std::abs(where[s][0] - at[s][0]), 10.0, 1.0) << "star " << s;
    RecordProperty("star" + std::to_string(s) + "_flux_spread", std::to_string((hi[s] - lo[s]) / lo[s]));
  }
}

}  // namespace
}  // namespace lc
