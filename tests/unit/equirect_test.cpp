// The equirectangular camera (camera/equirect.hpp): its directions against
// the projection's formula over the whole frame (the seam and the poles
// among the points), where it wraps, the warning for pixels that are not
// square, a window of the sphere, and a Schwarzschild shadow whose edge
// lands where the projection puts its angle at 2048 x 1024 (in the centre,
// across the seam and by a pole).

#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "camera/camera.hpp"
#include "camera/equirect.hpp"
#include "core/constants.hpp"
#include "shadow_check.hpp"

namespace lc {
namespace {

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

EquirectParams equirect(double longitude, double latitude, double yaw, double pitch, double roll) {
  EquirectParams p;
  p.longitude = longitude;
  p.latitude = latitude;
  p.yaw = yaw;
  p.pitch = pitch;
  p.roll = roll;
  return p;
}

// Over a grid of image points (pixel corners and centres: the seam at
// x = 0 and W, the poles at y = 0 and H among them), turned every way and
// for windows: every point has a ray, and its direction is the formula's
// to 1e-12 (a few roundings of numbers of order 1).
TEST(Equirect, DirectionsAreTheProjectionsFormula) {
  const int W = 64, H = 32;
  for (const auto& p : {equirect(360, 180, 0, 0, 0), equirect(360, 180, 30, -20, 10), equirect(120, 60, -120, 45, -75),
                        equirect(200, 180, 180, 0, 0)}) {
    const EquirectCamera cam(p, W, H);
    const CameraAxes& a = cam.axes();
    for (int jj = 0; jj <= 2 * H; ++jj)
      for (int ii = 0; ii <= 2 * W; ++ii) {
        const double px = 0.5 * ii, py = 0.5 * jj;
        const double lon = (px / W - 0.5) * p.longitude * degree, lat = (0.5 - py / H) * p.latitude * degree;
        const std::optional<CameraRay> r = cam.ray({px, py, 0.0});
        ASSERT_TRUE(r) << px << "," << py;
        const Vec3 d = r->direction;
        EXPECT_EQ(r->eye[0], 0.0);
        EXPECT_NEAR(dot(d, d), 1.0, 1e-12);
        EXPECT_NEAR(dot(d, a.forward), std::cos(lat) * std::cos(lon), 1e-12) << px << "," << py;
        EXPECT_NEAR(dot(d, a.right), std::cos(lat) * std::sin(lon), 1e-12) << px << "," << py;
        EXPECT_NEAR(dot(d, a.up), std::sin(lat), 1e-12) << px << "," << py;
      }
  }
}

// The whole sphere: the centre looks forward, the left and right edges
// both look backward (the seam), the top and bottom edges at up and down
// along their whole length; it wraps around and over the poles.  A window
// has edges.  Yawed a whole turn it is the same camera.
TEST(Equirect, TheWholeSphereWrapsAtTheSeamAndThePoles) {
  const EquirectCamera cam(equirect(360, 180, 0, 0, 0), 64, 32);
  const CameraAxes& a = cam.axes();
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(cam.direction(32, 16)[k], a.forward[k], 1e-15);
    EXPECT_NEAR(cam.direction(0, 16)[k], -a.forward[k], 1e-15);
    EXPECT_NEAR(cam.direction(64, 16)[k], -a.forward[k], 1e-15);
    EXPECT_NEAR(cam.direction(48, 16)[k], a.right[k], 1e-15);
    for (const double x : {0.0, 7.3, 40.0}) {
      EXPECT_NEAR(cam.direction(x, 0)[k], a.up[k], 1e-15);
      EXPECT_NEAR(cam.direction(x, 32)[k], -a.up[k], 1e-15);
    }
    // Past the pole the formula continues to the other side.
    EXPECT_NEAR(cam.direction(10.5, -0.5)[k], cam.direction(42.5, 0.5)[k], 1e-15);
    EXPECT_NEAR(cam.direction(-0.5, 3.5)[k], cam.direction(63.5, 3.5)[k], 1e-14);
  }
  EXPECT_EQ(cam.wrap(), (ImageWrap{true, true}));
  EXPECT_EQ(EquirectCamera(equirect(360, 180, 0, 0, 0), 63, 32).wrap(), (ImageWrap{true, false}));  // odd width
  EXPECT_EQ(EquirectCamera(equirect(360, 120, 0, 0, 0), 96, 32).wrap(), (ImageWrap{true, false}));
  EXPECT_EQ(EquirectCamera(equirect(200, 180, 0, 0, 0), 64, 32).wrap(), (ImageWrap{}));
  const EquirectCamera turned(equirect(360, 180, 360, 0, 0), 64, 32);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(turned.direction(20.5, 9.5)[k], cam.direction(20.5, 9.5)[k], 1e-14);
}

// Players and video sites expect square pixels: 2:1 for the whole sphere,
// the window's own ratio for a window.  Anything else is rendered but
// warned about, with what the frame should be.
TEST(Equirect, PixelsThatAreNotSquareAreWarnedAbout) {
  EXPECT_FALSE(EquirectCamera(equirect(360, 180, 0, 0, 0), 4096, 2048).size_warning());
  EXPECT_FALSE(EquirectCamera(equirect(180, 90, 0, 0, 0), 400, 200).size_warning());
  EXPECT_FALSE(EquirectCamera(equirect(120, 90, 0, 0, 0), 400, 300).size_warning());
  const auto w = EquirectCamera(equirect(360, 180, 0, 0, 0), 1280, 720).size_warning();
  ASSERT_TRUE(w);
  EXPECT_NE(w->find("not square"), std::string::npos) << *w;
  EXPECT_NE(w->find("a 360x180-degree window wants a frame 2 times as wide as it is high: a 1280x640 frame"),
            std::string::npos)
      << *w;
  // Float noise is not printed: 300 pixels of 1.2 degrees each make 360.
  const auto odd = EquirectCamera(equirect(360, 180, 0, 0, 0), 300, 200).size_warning();
  ASSERT_TRUE(odd);
  EXPECT_NE(odd->find("a 360x180-degree window"), std::string::npos) << *odd;
  // Top-bottom stereo: each eye's picture 2:1, the frame square.
  EquirectParams ods = equirect(360, 180, 0, 0, 0);
  ods.stereo = StereoLayout::top_bottom;
  EXPECT_FALSE(EquirectCamera(ods, 512, 512).size_warning());
  const auto flat_pair = EquirectCamera(ods, 512, 256).size_warning();
  ASSERT_TRUE(flat_pair);
  EXPECT_NE(flat_pair->find("each eye's picture 2 times as wide as it is high: a 512x512 frame"), std::string::npos)
      << *flat_pair;
  // Through the registry's Camera, as the render asks it.
  CameraSpec spec = equirect(360, 180, 0, 0, 0);
  EXPECT_TRUE(Camera(spec, 1280, 720).size_warning());
  EXPECT_FALSE(Camera(spec, 512, 256).size_warning());
  EXPECT_FALSE(Camera(CameraSpec{}, 1280, 720).size_warning());  // a pinhole has no such rule
}

// A window of the frame (render --region) is the whole frame's camera seen
// through it: each image point's ray is the whole frame's at the point it
// covers; it wraps only if as wide as the frame, never over the poles,
// and is a flat picture to a player.
TEST(Equirect, AWindowOfTheFrameIsTheFramesCameraThroughIt) {
  const CameraSpec spec = equirect(360, 180, 10, 20, 0);
  const Camera whole(spec, 64, 32), window(spec, 16, 8, ImageWindow{40, 4, 64, 32}), band(spec, 64, 8, ImageWindow{0, 4, 64, 32});
  for (const auto& [px, py] : {std::pair{0.5, 0.5}, std::pair{15.75, 7.25}, std::pair{-0.5, 3.0}}) {
    const Vec3 a = window.ray({px, py, 0.0})->direction, b = whole.ray({px + 40, py + 4, 0.0})->direction;
    const Vec3 c = window.direction(px, py);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a[k], b[k]);
      EXPECT_EQ(c[k], b[k]);
    }
  }
  EXPECT_EQ(window.wrap(), ImageWrap{});
  EXPECT_EQ(band.wrap(), (ImageWrap{true, false}));
  EXPECT_EQ(window.video_layout(), VideoLayout{});
  EXPECT_EQ(whole.video_layout().projection, VideoProjection::equirectangular);
  EXPECT_EQ(window.frame_height(), 32);
  ASSERT_EQ(window.pictures().size(), 1u);
  EXPECT_EQ(window.pictures()[0].width, 16);
}

// The shadow of a Schwarzschild hole at r = 30 M (9.6327 degrees) at
// 2048 x 1024: where the projection puts its angle, within a pixel, with
// the hole in the centre, across the seam (yawed half a turn: the shadow
// is cut in two, at the left and right edges), and near the south pole
// (pitched up 80 degrees: the shadow reaches to within 0.4 degrees of the
// pole and is stretched along the bottom rows).
TEST(Equirect, TheShadowsEdgeLandsWhereTheProjectionPutsItsAngle) {
  const double area = pi * std::pow(test::schwarzschild_shadow_angle_at_30() / degree * 1024 / 180, 2);  // pixels, at the equator
  for (const auto& p : {equirect(360, 180, 0, 0, 0), equirect(360, 180, 180, 0, 0), equirect(360, 180, 0, 80, 0)}) {
    const test::ShadowCheck c = test::check_shadow(p, 2048, 1024);
    EXPECT_EQ(c.wrong, 0) << "yaw " << p.yaw << " pitch " << p.pitch << ": " << c.first_wrong;
    // The shadow was in the frame: about its area in pixels at the
    // equator, more where the projection stretches it near a pole.
    EXPECT_GT(c.horizon, 0.9 * area) << "yaw " << p.yaw << " pitch " << p.pitch;
  }
}

}  // namespace
}  // namespace lc
