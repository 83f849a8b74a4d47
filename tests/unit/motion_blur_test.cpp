// Motion blur (docs/motion_blur.md) as the pictures show it: the renderer
// and the star stage taking each sample in its instant's scene.  The parts
// have tests of their own: shutter_test (the instants), frame_specs_test
// (the shot at each), sample_times_test (each sample's instant).  The
// pictures are checked against formulas in flat space: a sphere's image
// dragged across the view, a star's streak under a camera pan.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/constants.hpp"
#include "render/point_star_stage.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "render/trace.hpp"
#include "scratch_dir.hpp"
#include "script/shot.hpp"
#include "shot_file.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"
#include "stars/star_field.hpp"

namespace lc {
namespace {

using test::ScratchDir;
using test::write_shot;

// The frame's scene with its shutter, built at width x height.
Scene build_frame(Shot& shot, int frame, int width, int height, ShotResources& res) {
  return build_scene(shot.frame_specs(frame), width, height, res);
}

// A white sphere of radius R at rest on the x axis, moved by the script
// at speed v (M per frame) across the view of a static observer at
// (0, D, 0) looking at the origin, on a black sky: along the centre row a
// pixel's value is the share of its samples that meet the sphere.  With the
// shutter open (1 frame, centred, K = 16 instants, 4 x 4 samples), the
// limb at u(t) (the pinhole's projection of the tangent directions)
// sweeps from u(-1/2) to u(+1/2): the blurred row is the time average of
// the sharp coverages, so each limb ramps linearly across the distance it
// travels, and the image's centroid is where the sphere's is at mid-shutter.
TEST(MotionBlur, ASphereMovingAcrossTheViewRampsOverTheDistanceItTravels) {
  ScratchDir dir;
  const double D = 20, R = 2, v = 1.5, fov = 60;  // ~ 24 px of travel a frame at 256 px
  const auto file = write_shot(dir, "shot.lua", fmt::format(R"(local lc = require 'lightcone'
return {{name = 's', frames = 3, width = 256, height = 32, supersample = 4, shutter = 1, time_samples = 16,
  frame = function(i)
    return {{spacetime = lc.minkowski{{}}, observer = lc.static_observer{{x = 0, y = {}, z = 0}},
      camera = lc.camera{{fov = {}}},
      sky = lc.sky_checker{{colors = {{{{0, 0, 0}}, {{0, 0, 0}}}}}},
      objects = {{lc.sphere{{radius = {}, position = {{x = {} * (i - 1), y = 0, z = 0}},
                             colors = {{{{1, 1, 1}}, {{1, 1, 1}}}}}}}}}}
  end}})",
                                                D, fov, R, v));
  Shot shot(file);
  ShotResources res;
  const int W = 256, H = 32;
  RenderSettings rs{W, H, 4, false, true};
  const Scene blurred = build_frame(shot, 1, W, H, res);
  ASSERT_EQ(scene_get<Minkowski>(blurred).instants.size(), 16u);
  const FrameImage img = render_frame(blurred, rs, 2);
  // The pinhole's image coordinates of the limbs at time t (frames from
  // the frame's moment), the sphere at angle atan(x / D) from the axis.
  const double f = 0.5 * W / std::tan(0.5 * fov * degree);
  auto limbs = [&](double t) {
    const double x = v * t, d = std::hypot(x, D), centre = std::atan2(x, D), half = std::asin(R / d);
    return std::pair{0.5 * W + f * std::tan(centre - half), 0.5 * W + f * std::tan(centre + half)};
  };
  const int j = H / 2;
  auto value = [&](int i) { return static_cast<double>(img.rgb[3 * (static_cast<std::size_t>(j) * W + i)]); };
  double sum = 0, moment = 0;
  for (int i = 0; i < W; ++i) {
    sum += value(i);
    moment += value(i) * (i + 0.5);
  }
  // The expected coverage of pixel i: the time average over the shutter of
  // the share of [i, i+1] inside the sharp image at t, integrated finely.
  auto expected = [&](int i, int sign) {
    const int steps = 2000;
    double acc = 0;
    for (int s = 0; s < steps; ++s) {
      const double t = -0.5 + (s + 0.5) / steps;
      auto [a, b] = limbs(sign * t);
      acc += std::max(0.0, std::min<double>(i + 1, b) - std::max<double>(i, a));
    }
    return acc / steps;
  };
  double err_plus = 0, err_minus = 0;
  for (int i = 0; i < W; ++i) {
    err_plus = std::max(err_plus, std::abs(value(i) - expected(i, +1)));
    err_minus = std::max(err_minus, std::abs(value(i) - expected(i, -1)));
  }
  // (Which way the image's x runs against the scene's is the camera's
  // convention: the better of the two orientations is the one.)
  const int sign = err_plus < err_minus ? +1 : -1;
  // Each pixel is within sampling noise of the linear ramps: its 16
  // samples each sit at another instant and another sub-pixel, so a ramp
  // pixel's value is off by at most ~1/16 per quantisation of time (the
  // instants, 1.5 px apart at 24 px of travel) and of place (the 4
  // sub-columns), plus the ramps' curvature within a pixel: 0.15.
  const double err = std::min(err_plus, err_minus);
  EXPECT_LT(err, 0.15);

  // The ramps: where the value rises from 0 to 1 (leading and trailing
  // edges), spanning the limbs' travel.  Within 1.5 px at each end: the
  // last instant is half a time stratum (0.75 px of travel) inside the
  // shutter's end, and a pixel's sub-columns are 1/4 px apart.
  const auto [l0, r0] = limbs(-0.5 * sign);
  const auto [l1, r1] = limbs(+0.5 * sign);
  int first_lit = W, last_lit = -1, first_full = W, last_full = -1;
  for (int i = 0; i < W; ++i) {
    if (value(i) > 0) first_lit = std::min(first_lit, i), last_lit = i;
    if (value(i) >= 1) first_full = std::min(first_full, i), last_full = i;
  }
  EXPECT_NEAR(first_lit, std::min(l0, l1), 1.5);
  EXPECT_NEAR(last_lit + 1, std::max(r0, r1), 1.5);
  EXPECT_NEAR(first_full, std::max(l0, l1), 1.5);
  EXPECT_NEAR(last_full + 1, std::min(r0, r1), 1.5);
  // The centroid: the sphere's image at mid-shutter (t = 0: the image's
  // centre, as the sphere is on the axis then), within a quarter pixel.
  EXPECT_NEAR(moment / sum, 0.5 * W, 0.25);
  // And the light is the sharp frame's: the sphere's image area, averaged.
  double area = 0;
  for (int s = 0; s < 200; ++s) {
    auto [a, b] = limbs(-0.5 + (s + 0.5) / 200);
    area += (b - a) / 200;
  }
  EXPECT_NEAR(sum, area, 0.01 * area);
}

// A static scene: nothing changes within the shutter, so the frame renders
// as with the shutter closed, to the bit (and takes no more samples).
TEST(MotionBlur, AStaticSceneRendersTheSameWithTheShutterOpen) {
  ScratchDir dir;
  const auto file = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
return {name = 's', frames = 4, width = 48, height = 32, supersample = 2,
  frame = function(i)
    return {spacetime = lc.kerr{mass = 1, spin = 0.9}, observer = lc.static_observer{r = 30, theta = 80, phi = 0},
      camera = lc.camera{fov = 40}, disk = lc.disk{inner = 6, outer = 15}, sky = lc.sky_checker{}}
  end})");
  Shot shot(file);
  ShotResources res;
  RenderSettings rs{48, 32, 2, true, true};
  RenderStats closed_stats, open_stats;
  const FrameImage closed = render_frame(build_frame(shot, 2, 48, 32, res), rs, 2, &closed_stats);
  shot.set_shutter({.open = 1.0});
  const FrameImage open = render_frame(build_frame(shot, 2, 48, 32, res), rs, 2, &open_stats);
  EXPECT_EQ(closed.rgb, open.rgb);
  ASSERT_EQ(closed.layers.size(), open.layers.size());
  for (std::size_t l = 0; l < closed.layers.size(); ++l) EXPECT_EQ(closed.layers[l].values, open.layers[l].values);
  EXPECT_EQ(closed_stats.rays, open_stats.rays);
}

// A camera panning at a constant rate (yaw, degrees per frame) past a
// single star, 256 x 64 pixels, the shutter open the whole frame with K
// instants: the star drawn sharp (the frame's own scene alone) and blurred,
// on black, and the streak the pan's arc should draw, 2 f tan(pan / 2) on the
// image (f: the pinhole's focal length in pixels).
struct PannedStar {
  FrameImage sharp, blurred;
  double arc = 0;
  long sharp_images = 0, blurred_images = 0;
};
PannedStar pan_past_a_star(int time_samples) {
  ScratchDir dir;
  const double fov = 40, pan = 3.0;  // degrees a frame: ~19 px at 256 px
  const auto file = write_shot(dir, "shot.lua", fmt::format(R"(local lc = require 'lightcone'
return {{name = 's', frames = 3, width = 256, height = 64, shutter = 1, time_samples = {},
  frame = function(i)
    return {{spacetime = lc.minkowski{{}}, observer = lc.static_observer{{x = 0, y = 20, z = 0}},
      camera = lc.camera{{fov = {}, yaw = {} * (i - 1)}}, sky = lc.starfield{{faintest = -2}}}}
  end}})",
                                                time_samples, fov, pan));
  Shot shot(file);
  ShotResources res;
  const int W = 256, H = 64;
  const RenderSettings rs{W, H, 1, false, true};
  // The star where the frame's centre ray escapes (flat space: its own
  // direction, in the sky's frame).
  const Scene blurred_scene = build_frame(shot, 1, W, H, res);
  const auto& sc = scene_get<Minkowski>(blurred_scene);
  EXPECT_EQ(sc.instants.size(), static_cast<std::size_t>(time_samples));
  const RaySample centre = trace_sample(sc, unit3(sc.camera.direction(0.5 * W + 0.3, 0.5 * H + 0.2)));
  EXPECT_EQ(centre.hit.kind, HitKind::sky);
  const double th = centre.sky.theta, ph = centre.sky.phi;
  const auto field = std::make_shared<const StarField>(
      std::vector<PointStar>{{{std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)}, {1, 1, 1}}}, nullptr,
      nullptr);
  const PointStars star{field};
  PannedStar out;
  Scene sharp_scene = blurred_scene;
  scene_get<Minkowski>(sharp_scene).instants.clear();
  out.sharp = render_frame(sharp_scene, rs, 2);
  for (float& c : out.sharp.rgb) c = 0.0f;
  out.sharp_images = draw_point_stars(star, sc.camera, out.sharp.sky, out.sharp);
  out.blurred = render_frame(blurred_scene, rs, 2);
  EXPECT_EQ(out.blurred.sky_planes(), static_cast<std::size_t>(time_samples));
  for (float& c : out.blurred.rgb) c = 0.0f;
  std::vector<InstantStars> instants;
  for (const auto& at : sc.instants) instants.push_back({&star, &at.camera});
  out.blurred_images = draw_point_stars(std::span<const InstantStars>(instants), out.blurred.sky, out.blurred);
  const double f = 0.5 * W / std::tan(0.5 * fov * degree);
  out.arc = 2 * f * std::tan(0.5 * pan * degree);
  return out;
}

// A star's light along the rows: total, mean and variance of x.
struct Spread {
  double light = 0, mean = 0, var = 0;
};
Spread spread_of(const FrameImage& img) {
  Spread s;
  double m1 = 0, m2 = 0;
  for (int j = 0; j < img.height; ++j)
    for (int i = 0; i < img.width; ++i) {
      const double l = img.rgb[3 * (static_cast<std::size_t>(j) * img.width + i)];
      s.light += l;
      m1 += l * (i + 0.5);
      m2 += l * (i + 0.5) * (i + 0.5);
    }
  s.mean = m1 / s.light;
  s.var = m2 / s.light - s.mean * s.mean;
  return s;
}

// With the shutter open the star's image is a streak as long as the arc the
// pan sweeps during the shutter, within a pixel, and its light is the
// unblurred star's within 2%.  The streak's length is read from its light's
// spread along the row: a uniform streak of length L has variance L^2 / 12
// more than the sharp star's image.  With few instants (4: the star moves
// ~5 px from one to the next) as with many (32).
TEST(MotionBlur, APanDrawsAStarAsAStreakOfThePansArcWithItsLight) {
  for (const int K : {32, 4}) {
    const PannedStar p = pan_past_a_star(K);
    EXPECT_EQ(p.sharp_images, 1);
    EXPECT_EQ(p.blurred_images, K);
    const Spread a = spread_of(p.sharp), b = spread_of(p.blurred);
    const double length = std::sqrt(12 * (b.var - a.var));
    EXPECT_NEAR(length, p.arc, 1.0) << K << " instants; arc " << p.arc;
    EXPECT_NEAR(b.light, a.light, 0.02 * a.light) << K;
    EXPECT_NEAR(b.mean, a.mean, 0.5) << K;  // centred on the frame's moment
  }
}

// The streak is continuous however few the instants (docs/motion_blur.md):
// each instant's image is drawn along the star's path to halfway to the
// next, not as K dots.  Along the streak's row every pixel between its ends
// holds at least half the streak's mean light per pixel, where 4 dots 5 px
// apart left pixels dark between them.
TEST(MotionBlur, AStarsStreakHasNoGapsBetweenFewInstants) {
  const PannedStar p = pan_past_a_star(4);
  ASSERT_GT(p.arc, 16.0);  // instants ~5 px apart: dots would leave gaps
  const FrameImage& img = p.blurred;
  // The row holding most of the light, and its light per column.
  int row = 0;
  double best = -1;
  for (int j = 0; j < img.height; ++j) {
    double l = 0;
    for (int i = 0; i < img.width; ++i) l += img.rgb[3 * (static_cast<std::size_t>(j) * img.width + i)];
    if (l > best) best = l, row = j;
  }
  std::vector<double> column(static_cast<std::size_t>(img.width));
  for (int i = 0; i < img.width; ++i) {
    for (int j = std::max(0, row - 1); j <= std::min(img.height - 1, row + 1); ++j)
      column[static_cast<std::size_t>(i)] += img.rgb[3 * (static_cast<std::size_t>(j) * img.width + i)];
  }
  const Spread s = spread_of(img);
  const int first = static_cast<int>(std::ceil(s.mean - 0.5 * p.arc + 1.5));
  const int last = static_cast<int>(std::floor(s.mean + 0.5 * p.arc - 1.5));
  double sum = 0;
  for (int i = first; i <= last; ++i) sum += column[static_cast<std::size_t>(i)];
  const double mean = sum / (last - first + 1);
  for (int i = first; i <= last; ++i)
    EXPECT_GE(column[static_cast<std::size_t>(i)], 0.5 * mean) << "column " << i << " of the streak " << first << "-" << last;
}

// A free-falling observer: each instant's rays start from the worldline's
// event at the instant's proper time, with the frame transported there
// (Worldline::at_proper_time: what `lightcone geodesic` writes), and the
// frame is orthonormal to 1e-12.
TEST(MotionBlur, AFallsInstantsStartFromItsWorldlineAtTheirProperTime) {
  ScratchDir dir;
  const auto file = write_shot(dir, "shot.lua", R"(local lc = require 'lightcone'
local hole = lc.kerr{mass = 1, spin = 0.9}
local orbit = lc.worldline{spacetime = hole, start = {t = 0, r = 40, theta = 75, phi = 180},
                           velocity = {r = -0.4, theta = -0.11, phi = 0}, duration = 180}
return {name = 's', frames = 100, width = 16, height = 16, shutter = 0.5, time_samples = 4,
  frame = function(i)
    return {spacetime = hole, observer = lc.free_fall{worldline = orbit, proper_time = 1.7 * i}}
  end})");
  Shot shot(file);
  ShotResources res;
  const FrameSpecs specs = shot.frame_specs(50);
  ASSERT_TRUE(specs.blurred());
  const Scene scene = build_scene(specs, 16, 16, res);
  const auto& sc = scene_get<Kerr>(scene);
  const auto& w = std::get<FreeFall::Params>(specs.frame.observer).worldline;
  const auto worldline = res.worldline(w);
  ASSERT_EQ(sc.instants.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const auto& at = sc.instants[k];
    const double tau = 1.7 * (50 + specs.times[k]);
    const WorldlineEvent ev = worldline->at_proper_time(tau);
    for (int mu = 0; mu < 4; ++mu) {
      EXPECT_EQ(at.eye.event[mu], ev.x[mu]) << k;
      for (int a = 0; a < 4; ++a) EXPECT_EQ(at.eye.frame.e[a][mu], ev.frame.e[a][mu]) << k;
    }
    // Orthonormal: g(e_a, e_b) = eta_ab.
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        double g = 0;
        for (int m = 0; m < 4; ++m)
          for (int n = 0; n < 4; ++n) g += at.eye.metric[m][n] * at.eye.frame.e[a][m] * at.eye.frame.e[b][n];
        EXPECT_NEAR(g, a == b ? (a == 0 ? -1.0 : 1.0) : 0.0, 1e-12) << k << " " << a << b;
      }
    // A camera ray at the instant's time starts from that eye.
    EyePool eyes;
    const RayStart start = eyes.start(at, CameraRay{{1, 0, 0}, {}, specs.times[k]});
    EXPECT_EQ(start.eye, &at.eye);
    // ... and not in another instant's scene.
    EXPECT_THROW(eyes.start(sc, CameraRay{{1, 0, 0}, {}, specs.times[k]}), std::logic_error);
  }
}

}  // namespace
}  // namespace lc
