// Rendering against figures known independently: the shadow size of a
// Schwarzschild hole, the exact flat-space projection of the disk, the
// rotational symmetry of a disk seen along the axis, the angular size of a
// sphere in flat space, and identical images for any thread count.

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"

namespace lc {
namespace {

struct NoPath {
  void operator()(const RayStep&) const {}
};

FrameScene kerr_scene(double M, double a, double r, double theta_deg, double fov, bool disk) {
  FrameScene fs;
  fs.spacetime = Kerr(M, a);
  fs.observer.kind = ObserverKind::static_observer;
  fs.observer.position = {0, r, theta_deg * degree, 0};
  fs.camera.fov = fov;
  if (disk) fs.disk = DiskSpec{6, 15, 9, 24};
  return fs;
}

RaySample sample_at(const Scene& scene, double px, double py) {
  return std::visit([&](const auto& sc) { return trace_sample(sc, sc.camera.direction(px, py), NoPath{}); }, scene);
}

TEST(Render, SchwarzschildShadowAngularRadius) {
  // A static observer at r = 30 sees the shadow edge at
  // arcsin(sqrt(27) M sqrt(1 - 2M/r) / r) = 9.6327 deg (Synge 1966).
  const double expected = std::asin(std::sqrt(27.0) * std::sqrt(1 - 2 / 30.0) / 30.0) / degree;
  EXPECT_NEAR(expected, 9.6327, 1e-4);
  ShotResources res;
  const int W = 200;
  const Scene scene = build_scene(kerr_scene(1, 0, 30, 90, 30, false), W, 1, res);
  // Along the centre row, the angle from the axis of pixel coordinate px is
  // atan((2 px / W - 1) tan(15 deg)).  Bisect for the edge, then compare.
  double lo = W / 2.0, hi = W;  // centre: horizon; right edge: sky
  ASSERT_EQ(sample_at(scene, lo, 0.5).kind, HitKind::horizon);
  ASSERT_EQ(sample_at(scene, hi, 0.5).kind, HitKind::sky);
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (sample_at(scene, mid, 0.5).kind == HitKind::horizon ? lo : hi) = mid;
  }
  const double angle = std::atan((2 * lo / W - 1) * std::tan(15 * degree)) / degree;
  EXPECT_NEAR(angle, expected, 2e-4);  // the integrator decides the edge to ~1e-6 rad
  // And in pixel terms: within one pixel of the predicted edge.
  const double px = W / 2.0 * (1 + std::tan(expected * degree) / std::tan(15 * degree));
  EXPECT_NEAR(lo, px, 1.0);
}

TEST(Render, FlatSpaceDiskIsTheExactProjection) {
  // M = 0: each pixel's disk hit is where the straight line from the camera
  // meets z = 0.
  const int W = 48, H = 48;
  ShotResources res;
  const FrameScene fs = kerr_scene(0, 0, 30, 70, 50, true);
  const Scene scene = build_scene(fs, W, H, res);
  const Vec3 cam = {30 * std::sin(70 * degree), 0, 30 * std::cos(70 * degree)};
  const PinholeCamera camera(fs.camera, W, H);
  int disk_pixels = 0;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const Vec3 n = camera.direction(i + 0.5, j + 0.5);
      // Legs of the static frame at (theta, phi = 0) in flat space: e_r, e_theta, e_phi.
      const double th = 70 * degree;
      const Vec3 er = {std::sin(th), 0, std::cos(th)}, et = {std::cos(th), 0, -std::sin(th)}, ep = {0, 1, 0};
      const Vec3 d = {n[0] * er[0] + n[1] * et[0] + n[2] * ep[0], n[0] * er[1] + n[1] * et[1] + n[2] * ep[1],
                      n[0] * er[2] + n[1] * et[2] + n[2] * ep[2]};
      const RaySample s = sample_at(scene, i + 0.5, j + 0.5);
      if (d[2] >= 0) {
        EXPECT_EQ(s.kind, HitKind::sky);
        continue;
      }
      const double k = -cam[2] / d[2];
      const double x = cam[0] + k * d[0], y = cam[1] + k * d[1];
      const double r = std::hypot(x, y);
      if (r < 6 || r > 15) {
        EXPECT_EQ(s.kind, HitKind::sky) << i << "," << j;
        continue;
      }
      ++disk_pixels;
      ASSERT_EQ(s.kind, HitKind::disk) << i << "," << j;
      EXPECT_NEAR(s.r, r, 1e-7 * r);
      double phi = std::atan2(y, x);
      if (phi < 0) phi += two_pi;
      EXPECT_NEAR(std::remainder(s.phi - phi, two_pi), 0.0, 1e-7);
      EXPECT_EQ(s.order, 0);
    }
  EXPECT_GT(disk_pixels, 200);
}

TEST(Render, DiskSeenAlongTheAxisIsRotationallySymmetric) {
  // Schwarzschild, observer on the axis (theta = 0): a quarter turn about the
  // image centre maps the picture onto itself, pixel centre to pixel centre.
  const int W = 40;
  ShotResources res;
  RenderSettings rs{W, W, 1, true};
  const Scene scene = build_scene(kerr_scene(1, 0, 30, 0, 60, true), W, W, res);
  const FrameImage img = render_frame(scene, rs, 2);
  const auto& kind = img.layers[0].values;
  const auto& r = img.layers[1].values;
  int disk = 0, horizon = 0;
  for (int j = 0; j < W; ++j)
    for (int i = 0; i < W; ++i) {
      const int p = j * W + i, q = i * W + (W - 1 - j);  // (i, j) -> (W-1-j, i)
      EXPECT_EQ(kind[p], kind[q]) << i << "," << j;
      if (kind[p] == 1.0f) {
        ++disk;
        EXPECT_NEAR(r[p], r[q], 1e-4f * r[p]);  // float layer; the physics agrees to ~1e-9
      }
      if (kind[p] == 2.0f) ++horizon;
    }
  EXPECT_GT(disk, 100);
  EXPECT_GT(horizon, 10);
}

TEST(Render, SphereInFlatSpaceHasItsAngularSize) {
  FrameScene fs;
  fs.spacetime = Dihole(0.0, 0.0, 1.0);
  fs.observer.position = {0, 0, 80, 0};
  fs.camera.fov = 12;
  SphereSpec sp;
  sp.radius = 1.0;
  sp.position = Vec4{0, 5, 0, 0};
  fs.spheres.push_back(sp);
  ShotResources res;
  const int W = 400;
  const Scene scene = build_scene(fs, W, 1, res);
  // The sphere's centre is at angle atan(5/80) to the right of forward
  // (forward = -y, right = e_phi = -x at phi = 90 deg... the observer at
  // (0, 80, 0) has e_phi = (-1, 0, 0), so +x is to the left).
  const double t = std::tan(6 * degree);
  auto px_of = [&](double angle) { return W / 2.0 * (1 + std::tan(angle) / t); };
  const double centre = std::atan2(-5.0, 80.0), half = std::asin(1.0 / std::hypot(5.0, 80.0));
  EXPECT_EQ(sample_at(scene, px_of(centre), 0.5).kind, HitKind::object);
  // Bisect the right edge (limb) of the disc in the image.
  double lo = px_of(centre), hi = px_of(centre + 2 * half);
  ASSERT_EQ(sample_at(scene, hi, 0.5).kind, HitKind::sky);
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (sample_at(scene, mid, 0.5).kind == HitKind::object ? lo : hi) = mid;
  }
  // The limb is where the line of sight is tangent: angle centre + half.
  EXPECT_NEAR(std::atan((2 * lo / W - 1) * t), centre + half, 1e-6);
}

TEST(Render, ThreadCountDoesNotChangeTheImage) {
  const int W = 24, H = 18;
  ShotResources res;
  RenderSettings rs{W, H, 2, true};
  const Scene scene = build_scene(kerr_scene(1, 0.9, 30, 80, 40, true), W, H, res);
  const FrameImage one = render_frame(scene, rs, 1);
  const FrameImage three = render_frame(scene, rs, 3);
  EXPECT_EQ(one.rgb, three.rgb);
  for (std::size_t k = 0; k < one.layers.size(); ++k) EXPECT_EQ(one.layers[k].values, three.layers[k].values);
}

TEST(Render, RefusesObserversThatCannotExist) {
  ShotResources res;
  EXPECT_THROW(build_scene(kerr_scene(1, 0.9, 1.8, 90, 40, false), 8, 8, res), std::invalid_argument);  // ergoregion
  EXPECT_THROW(build_scene(kerr_scene(1, 0.9, 1.2, 90, 40, false), 8, 8, res), std::invalid_argument);  // horizon
}

}  // namespace
}  // namespace lc
