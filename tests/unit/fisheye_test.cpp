// The fisheye camera (camera/fisheye.hpp): its directions against the
// equidistant projection's formula, the disc it has rays in, the tilt, and
// a Schwarzschild shadow whose edge lands where the projection puts its
// angle (Synge's 9.6327 degrees from r = 30 M), with no ray traced outside
// the disc.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "camera/camera.hpp"
#include "camera/fisheye.hpp"
#include "core/constants.hpp"
#include "render/pixel_rows.hpp"
#include "render/scene_builder.hpp"
#include "shadow_check.hpp"
#include "spacetime/kerr.hpp"
#include "test_scenes.hpp"

namespace lc {
namespace {

using Point = std::pair<double, double>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

FisheyeParams fisheye(double field, double tilt, double yaw, double pitch, double roll) {
  FisheyeParams p;
  p.full_angle = field;
  p.tilt = tilt;
  p.yaw = yaw;
  p.pitch = pitch;
  p.roll = roll;
  return p;
}

// Over a grid of image points (pixel corners and centres, so the disc's
// edge at the middle of each side is among them), with and without a tilt
// and turned every way: a ray exactly where the point is within the disc,
// and its direction the formula's — at angle rho * field / 2 from the
// axis, towards (x right + y up) — to 1e-12 (a few roundings of numbers of
// order 1).
TEST(Fisheye, DirectionsAreTheEquidistantProjection) {
  const int W = 64, H = 48;
  for (const auto& p : {fisheye(180, 0, 0, 0, 0), fisheye(360, 0, 30, -20, 10), fisheye(90, 0, -120, 45, -75),
                        fisheye(220, 15, 10, 60, 0), fisheye(180, 30, 0, 0, 25)}) {
    const FisheyeCamera cam(p, W, H);
    const CameraAxes& a = cam.axes();
    const double R = 0.5 * H;  // the shorter side's half
    int inside = 0, outside = 0;
    for (int jj = 0; jj <= 2 * H; ++jj)
      for (int ii = 0; ii <= 2 * W; ++ii) {
        const double px = 0.5 * ii, py = 0.5 * jj;
        const double x = (px - 0.5 * W) / R, y = (0.5 * H - py) / R, rho = std::hypot(x, y);
        const std::optional<CameraRay> r = cam.ray({px, py, 0.0});
        ASSERT_EQ(r.has_value(), rho <= 1.0) << px << "," << py;
        const Vec3 d = cam.direction(px, py);
        if (r) {
          ++inside;
          // One projection (along) behind both; the compiler may fuse its
          // multiply-adds differently where it inlines each (GCC 14 does),
          // so the two agree to rounding, not always to the bit.
          for (int k = 0; k < 3; ++k) EXPECT_NEAR(r->direction[k], d[k], 4e-16);
          EXPECT_EQ(r->eye[0], 0.0);
        } else {
          ++outside;
        }
        const double angle = std::min(rho * 0.5 * p.full_angle * degree, pi);
        EXPECT_NEAR(dot(d, d), 1.0, 1e-12);
        EXPECT_NEAR(dot(d, a.forward), std::cos(angle), 1e-12) << px << "," << py;
        const double s = rho > 0 ? std::sin(angle) / rho : 0.0;
        EXPECT_NEAR(dot(d, a.right), s * x, 1e-12) << px << "," << py;
        EXPECT_NEAR(dot(d, a.up), s * y, 1e-12) << px << "," << py;
      }
    EXPECT_GT(inside, 1000);
    EXPECT_GT(outside, 1000);
  }
}

// The disc touches the middle of each side of a square frame: the points
// there have rays, at half the field from the axis; the corners have none.
TEST(Fisheye, TheDiscTouchesTheSidesOfASquareFrame) {
  const FisheyeCamera cam(fisheye(180, 0, 0, 0, 0), 100, 100);
  for (const auto& [px, py] : {Point{50.0, 0.0}, Point{100.0, 50.0}, Point{50.0, 100.0}, Point{0.0, 50.0}}) {
    const std::optional<CameraRay> r = cam.ray({px, py, 0.0});
    ASSERT_TRUE(r) << px << "," << py;
    EXPECT_NEAR(dot(r->direction, cam.axes().forward), 0.0, 1e-15);
  }
  for (const auto& [px, py] : {Point{0.5, 0.5}, Point{99.5, 0.5}, Point{0.5, 99.5}, Point{99.5, 99.5}})
    EXPECT_FALSE(cam.ray({px, py, 0.0})) << px << "," << py;
  // The top edge's middle looks along up, the right edge's along right.
  const Vec3 top = cam.ray({50.0, 0.0, 0.0})->direction, right = cam.ray({100.0, 50.0, 0.0})->direction;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(top[k], cam.axes().up[k], 1e-15);
    EXPECT_NEAR(right[k], cam.axes().right[k], 1e-15);
  }
}

// A tilt turns the axis from forward towards down: without a roll it is a
// pitch down by the same angle, by turned_axes' own arithmetic.
TEST(Fisheye, TheTiltTurnsTheAxisDown) {
  for (const double tilt : {0.0, 15.0, 30.0, 90.0}) {
    const FisheyeCamera tilted(fisheye(180, tilt, 20, 35, 0), 32, 32);
    const CameraAxes pitched = turned_axes(20, 35 - tilt, 0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(tilted.axes().forward[k], pitched.forward[k], 1e-15) << tilt;
      EXPECT_NEAR(tilted.axes().up[k], pitched.up[k], 1e-15) << tilt;
      EXPECT_NEAR(tilted.axes().right[k], pitched.right[k], 1e-15) << tilt;
    }
  }
}

// Schwarzschild, a static observer at r = 30 M looking at the hole through
// a 180-degree fisheye at 256x256: the shadow's edge is at 9.6327 degrees
// from the hole (sin = 3 sqrt(3) M / r sqrt(1 - 2M/r), Synge 1966), so at
// 9.6327 / 90 of the disc's radius from the image centre; along the centre
// row and column the last horizon pixel and the first sky pixel straddle it
// within a pixel.  Outside the disc nothing is traced: black, alpha 0,
// hit.kind "no ray", and fewer rays than pixels.
TEST(Fisheye, TheShadowsEdgeLandsWhereTheProjectionPutsItsAngle) {
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0);
  fs.observer = StaticObserver::Params{{0, 30, 90 * degree, 0}};
  fs.camera = fisheye(180, 0, 0, 0, 0);
  ShotResources res;
  const RenderSettings rs{256, 256, 1, true, false};
  const auto sc = scene_get<Kerr>(build_scene(fs, rs.width, rs.height, res));
  FrameImage img = make_frame(rs);
  std::vector<int> rows;
  for (int j = 0; j < rs.height; ++j) rows.push_back(j);
  const RenderStats stats = render_rows_with(sc, sc.camera, rs, std::span<const int>(rows), img, nullptr,
                                             pixel_rows::TraceRays{});
  const double edge = std::asin(3 * std::sqrt(3.0) / 30 * std::sqrt(1 - 2.0 / 30)) / degree;
  ASSERT_NEAR(edge, 9.6327, 1e-4);
  const double radius_px = edge / 90.0 * 128.0;  // ~13.7 pixels
  auto kind = [&](int i, int j) { return img.layers[0].values[static_cast<std::size_t>(j) * rs.width + i]; };
  const float horizon = static_cast<float>(HitKind::horizon), no_ray = static_cast<float>(HitKind::no_ray);
  // The shadow's extent along the centre row and column, from pixel centres.
  int lo = 128, hi = 127, top = 128, bottom = 127;
  for (int i = 0; i < rs.width; ++i)
    if (kind(i, 128) == horizon) lo = std::min(lo, i), hi = std::max(hi, i);
  for (int j = 0; j < rs.height; ++j)
    if (kind(128, j) == horizon) top = std::min(top, j), bottom = std::max(bottom, j);
  // Pixel centres at i + 0.5; the image centre at 128.
  EXPECT_NEAR(128.0 - (lo + 0.5), radius_px, 1.0);
  EXPECT_NEAR((hi + 0.5) - 128.0, radius_px, 1.0);
  EXPECT_NEAR(128.0 - (top + 0.5), radius_px, 1.0);
  EXPECT_NEAR((bottom + 0.5) - 128.0, radius_px, 1.0);
  // Outside the disc: black, transparent, untraced.
  long without = 0;
  for (int j = 0; j < rs.height; ++j)
    for (int i = 0; i < rs.width; ++i) {
      const double x = i + 0.5 - 128.0, y = j + 0.5 - 128.0;
      const std::size_t p = static_cast<std::size_t>(j) * rs.width + i;
      if (x * x + y * y > 128.0 * 128.0) {
        ++without;
        EXPECT_EQ(kind(i, j), no_ray);
        EXPECT_EQ(img.alpha[p], 0.0f);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(img.rgb[3 * p + c], 0.0f);
      } else {
        EXPECT_EQ(img.alpha[p], 1.0f);
        EXPECT_NE(kind(i, j), no_ray);
      }
    }
  EXPECT_EQ(stats.rays + without, static_cast<long>(rs.width) * rs.height);
  EXPECT_EQ(stats.gave_up, 0);
}

// The same shadow at a dome master's size, 1024 x 1024, through the whole
// disc's projection (test::check_shadow: every pixel of the rows near the
// shadow on the side its centre's angle says, within a pixel of the edge):
// with the hole at the centre, and framed as for a tilted dome (tilt 15,
// pitch 55, yawed a whole turn), where it sits 40 degrees from the axis
// and the projection stretches it sideways.
TEST(Fisheye, AtADomeMastersSizeTheShadowsEdgeLandsWhereTheProjectionPutsIt) {
  const double area = pi * std::pow(test::schwarzschild_shadow_angle_at_30() / degree * 512 / 90, 2);  // at the centre
  for (const auto& p : {fisheye(180, 0, 0, 0, 0), fisheye(180, 15, 360, 55, 0)}) {
    const test::ShadowCheck c = test::check_shadow(p, 1024, 1024);
    EXPECT_EQ(c.wrong, 0) << "tilt " << p.tilt << ": " << c.first_wrong;
    EXPECT_GT(c.horizon, 0.9 * area) << "tilt " << p.tilt;
  }
}

}  // namespace
}  // namespace lc
