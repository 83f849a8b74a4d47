// Stereo frames (camera/stereo.hpp): both eyes' pictures in one frame,
// each the camera's projection at the picture's size; the stereo pinhole's
// parallel eyes; omnidirectional stereo (ODS) on the equirect: its eyes on
// the circle, tangent rays, the merge towards the poles, and in flat space
// the disparity of a sphere at distance D where ODS's geometry puts it;
// the star stage drawing each eye's picture as a frame of its own.

#include "camera/equirect.hpp"
#include "camera/pinhole.hpp"
#include "camera/stereo.hpp"
#include "objects/sphere.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/minkowski.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "camera/camera.hpp"
#include "core/constants.hpp"
#include "render/pixel_rows.hpp"
#include "render/point_star_stage.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "render/trace.hpp"
#include "stars/sky_quad.hpp"

namespace lc {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

TEST(Stereo, AFrameHoldsBothEyesPictures) {
  const StereoFrame tb(StereoLayout::top_bottom, 64, 64), sbs(StereoLayout::side_by_side, 128, 32),
      mono(StereoLayout::mono, 40, 30);
  EXPECT_EQ(tb.eye_width(), 64);
  EXPECT_EQ(tb.eye_height(), 32);
  EXPECT_EQ(sbs.eye_width(), 64);
  EXPECT_EQ(sbs.eye_height(), 32);
  const EyePoint top = tb.view(10.5, 31.5), bottom = tb.view(10.5, 32.0), right = sbs.view(64.25, 3.0);
  EXPECT_EQ(top.eye, -1);
  EXPECT_EQ(top.py, 31.5);
  EXPECT_EQ(bottom.eye, 1);
  EXPECT_EQ(bottom.py, 0.0);
  EXPECT_EQ(right.eye, 1);
  EXPECT_EQ(right.px, 0.25);
  EXPECT_EQ(mono.view(3.0, 4.0).eye, 0);
  ASSERT_EQ(tb.pictures().size(), 2u);
  EXPECT_EQ(tb.pictures()[1].y0, 32);
  EXPECT_EQ(sbs.pictures()[1].x0, 64);
  EXPECT_EQ(mono.pictures().size(), 1u);
}

// The stereo pinhole: each eye's picture is the mono pinhole at the
// picture's size, seen from half the separation left (top picture) and
// right (bottom) of the observer along the camera's right.
TEST(Stereo, ThePinholesEyesAreParallelAndApart) {
  PinholeParams p;
  p.fov = 50;
  p.yaw = 20;
  p.pitch = -10;
  p.stereo = StereoLayout::top_bottom;
  p.separation = 0.8;
  const PinholeCamera cam(p, 64, 72);
  PinholeParams m = p;
  m.stereo = StereoLayout::mono;
  const PinholeCamera mono(m, 64, 36);
  for (const auto& [px, py, eye] : {std::tuple{10.5, 3.5, -1}, std::tuple{10.5, 39.5, 1}, std::tuple{63.0, 71.0, 1}}) {
    const auto r = cam.ray({px, py, 0.0});
    ASSERT_TRUE(r);
    const Vec3 want = mono.direction(px, eye < 0 ? py : py - 36);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(r->direction[k], want[k], 1e-15);
      EXPECT_NEAR(r->eye[k], eye * 0.4 * cam.axes().right[k], 1e-15);
    }
  }
  EXPECT_EQ(cam.video_layout(), (VideoLayout{VideoProjection::flat, StereoLayout::top_bottom}));
  // A mono pinhole's rays start at the observer, as they always did.
  EXPECT_TRUE(mono.ray({3.0, 4.0, 0.0})->at_observer());
}

// ODS: every ray leaves its eye tangent to the circle of radius
// separation / 2 (the eye at right angles to the ray's longitude, in the
// forward-right plane, the left eye to the left); the radius is whole to
// 60 degrees of latitude, none from 75, linear between.
TEST(Stereo, OdsEyesAreOnTheCircleAndMergeAtThePoles) {
  EquirectParams p;
  p.stereo = StereoLayout::top_bottom;
  p.separation = 2.0;
  p.yaw = 30;
  p.roll = 10;
  const int W = 360, H = 360;  // eye pictures 360 x 180: a degree a pixel
  const EquirectCamera cam(p, W, H);
  const CameraAxes& a = cam.axes();
  for (int eye : {-1, 1})
    for (double lon = -179.5; lon < 180; lon += 7.25)
      for (double lat : {0.5, 45.5, -59.5, 62.0, -70.5, 75.5, 89.5}) {
        const double px = lon + 180, py = 90 - lat + (eye > 0 ? 180 : 0);
        const auto r = cam.ray({px, py, 0.0});
        ASSERT_TRUE(r);
        const double want = std::clamp((75 - std::abs(lat)) / 15, 0.0, 1.0);
        EXPECT_NEAR(std::sqrt(dot(r->eye, r->eye)), want, 1e-12) << lon << " " << lat;
        // In the forward-right plane, at right angles to the ray.
        EXPECT_NEAR(dot(r->eye, a.up), 0.0, 1e-12);
        EXPECT_NEAR(dot(r->eye, r->direction), 0.0, 1e-12) << lon << " " << lat;
        // The left eye to the left of the ray's horizontal direction.
        const Vec3 h = {std::cos(lon * degree), std::sin(lon * degree), 0.0};  // (forward, right) components
        const double side = h[0] * dot(r->eye, a.right) - h[1] * dot(r->eye, a.forward);
        if (want > 0) EXPECT_EQ(side > 0 ? 1 : -1, eye) << lon << " " << lat;
      }
  EXPECT_EQ(cam.video_layout(), (VideoLayout{VideoProjection::equirectangular, StereoLayout::top_bottom}));
  EXPECT_EQ(cam.pictures().size(), 2u);
  EXPECT_EQ(cam.wrap(), (ImageWrap{true, true}));  // each eye's picture wraps
  EXPECT_FALSE(cam.size_warning());               // a square frame of two 2:1 pictures
}

// In flat space (the dihole without masses) a sphere of radius R = 0.5 M at
// distance D = 20 M ahead, through ODS of separation 2 r (r = 1 M): a
// column at longitude lon of the right eye sees the sphere where its
// tangent ray passes within R of the centre, D sin(-lon) - r in [-R, R],
// so lon in [-asin((r + R)/D), -asin((r - R)/D)]; the left eye the mirror
// image.  The sphere's centre is seen 2 asin(r / D) apart by the two eyes
// (ODS's disparity of a point at distance D).  The first and last pixel
// centres on the sphere along each eye's equator row: within a pixel.
TEST(Stereo, OdsDisparityInFlatSpaceIsTheFormulas) {
  const double D = 20, R = 0.5, r = 1;
  SceneSpec fs;
  fs.spacetime = Dihole(0.0, 0.0, 1.0);
  fs.observer = StaticObserver::Params{{0, 0, D, 0}};
  EquirectParams p;
  p.stereo = StereoLayout::top_bottom;
  p.separation = 2 * r;
  fs.camera = p;
  Sphere::Params sp;
  sp.radius = R;
  sp.placement.at = Vec4{0, 0, 0, 0};
  fs.objects.push_back(sp);
  ShotResources res;
  const int W = 1440;  // 4 pixels a degree; eye pictures 1440 x 720
  const RenderSettings rs{W, W, 1, true, false};
  const auto sc = scene_get<Dihole>(build_scene(fs, W, W, res));
  FrameImage img = make_frame(rs);
  const std::vector<int> rows = {360, 1080};  // each eye's row just below its equator (-0.125 degrees)
  const RenderStats stats = render_rows_with(sc, sc.camera, rs, std::span<const int>(rows), img, nullptr,
                                             pixel_rows::TraceRays{});
  EXPECT_EQ(stats.gave_up, 0);
  auto column_of = [&](double lon) { return (lon / 360 + 0.5) * W; };  // degrees -> pixel units
  double centre[2];
  for (int e = 0; e < 2; ++e) {
    int first = -1, last = -1;
    for (int i = 0; i < W; ++i)
      if (img.layers[0].values[static_cast<std::size_t>(rows[e]) * W + i] == static_cast<float>(Sphere::hit_kind)) {
        if (first < 0) first = i;
        last = i;
      }
    ASSERT_GE(first, 0) << "eye " << e;
    const double sign = e == 0 ? 1 : -1;  // the left eye sees it to the right
    const double near_limb = sign * std::asin((r - R) / D) / degree, far_limb = sign * std::asin((r + R) / D) / degree;
    EXPECT_NEAR(first + 0.5, column_of(std::min(near_limb, far_limb)), 1.0) << "eye " << e;
    EXPECT_NEAR(last + 0.5, column_of(std::max(near_limb, far_limb)), 1.0) << "eye " << e;
    centre[e] = 0.5 * (first + last + 1);
  }
  EXPECT_NEAR((centre[0] - centre[1]) / W * 360, 2 * std::asin(r / D) / degree, 2.0 * 360 / W);
}

// Point stars on a stereo frame: each eye's picture is drawn as a frame of
// its own, so a star is drawn once in each (two images), its light whole
// in each, and nothing lands across the line between the pictures.
TEST(Stereo, PointStarsAreDrawnInEachEyesPictureOnce) {
  const int W = 64, H = 72;  // two 64 x 36 pictures
  SceneSpec fs;
  fs.spacetime = Minkowski{};
  fs.observer = StaticObserver::Params{{0, 0, 40, 0}};
  PinholeParams p;
  p.fov = 20;
  p.stereo = StereoLayout::top_bottom;
  p.separation = 0.5;
  fs.camera = p;
  PointStarSky::Params sky;
  sky.background = "none";
  fs.sky = sky;
  RenderSettings rs{W, H, 1, false};
  ShotResources res;
  const Scene scene = build_scene(fs, W, H, res);
  const Camera camera(fs.camera, W, H);
  // A star at infinity where the pictures' point (20.3, 35.9) looks, 0.1
  // pixels above their bottom edges (in flat space every eye sees a star
  // at infinity along the same direction).
  std::vector<PointStar> stars;
  {
    const auto& sc = scene_get<Minkowski>(scene);
    const Vec3 dir = camera.direction(20.3, 35.9);
    RaySample s;
    trace_batch(sc, std::span<const Vec3>(&dir, 1), std::span<RaySample>(&s, 1));
    ASSERT_TRUE(s.sky.reached());
    const double t = s.sky.theta, ph = s.sky.phi;
    stars.push_back({{std::sin(t) * std::cos(ph), std::sin(t) * std::sin(ph), std::cos(t)}, {1, 1, 1}, 0.0});
  }
  FrameImage image = make_frame(rs);
  prepare_frame(scene, image);
  std::vector<int> rows(H);
  std::iota(rows.begin(), rows.end(), 0);
  render_rows(scene, rs, rows, image);
  const PointStars points{std::make_shared<const StarField>(stars, nullptr, nullptr), 0.0, 0.0};
  std::fill(image.rgb.begin(), image.rgb.end(), 0.0f);
  EXPECT_EQ(draw_point_stars(points, camera, image.sky, image), 2);
  double light[2] = {0, 0};
  int lit_rows[2][2] = {{H, -1}, {H, -1}};
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      const float v = image.rgb[3 * static_cast<std::size_t>(j * W + i)];
      if (v <= 0) continue;
      const int e = j < 36 ? 0 : 1, pj = j % 36;
      light[e] += v * SkyQuad{{unit3(camera.direction(i, pj)), unit3(camera.direction(i + 1, pj)),
                               unit3(camera.direction(i + 1, pj + 1)), unit3(camera.direction(i, pj + 1))}}
                          .area();
      lit_rows[e][0] = std::min(lit_rows[e][0], j), lit_rows[e][1] = std::max(lit_rows[e][1], j);
    }
  // The star sits 0.1 pixels above each picture's bottom edge: the tent
  // filter's share beyond the edge (0.4 of it) is lost, as at any frame's
  // edge, rather than landing on the other eye's picture.
  EXPECT_NEAR(light[0], 0.6, 0.012);
  EXPECT_NEAR(light[1], 0.6, 0.012);
  EXPECT_EQ(lit_rows[0][1], 35);  // none of the left picture's star below its picture
  EXPECT_EQ(lit_rows[1][0], 71);  // the right eye's at the bottom of its own
}

}  // namespace
}  // namespace lc
