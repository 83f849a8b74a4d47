// Reusing samples between frames of a still scene: a frame rendered with
// samples kept from an earlier one must be the frame rendered from scratch,
// while a moving sphere changes what the rays near it see.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <numeric>

#include "camera/pinhole.hpp"
#include "objects/sphere.hpp"
#include "render/renderer.hpp"
#include "render/sample_memo.hpp"
#include "render/scene_builder.hpp"
#include "render/trace.hpp"
#include "script/shot.hpp"
#include "spacetime/dihole.hpp"
#include "test_scenes.hpp"

namespace lc {
namespace {

// The paper's dihole with its oscillating sphere, seen by a static observer
// at time t.
SceneSpec dihole_at(double t) {
  SceneSpec fs;
  fs.spacetime = Dihole(0.4, 0.4, 1.0);
  fs.observer = StaticObserver::Params{{t, 0, 40, 0}};
  fs.camera.get<PinholeCamera::Params>().fov = 30;
  fs.objects.push_back(test::falling_sphere(fs.spacetime, {0, 5, 0, 0}, {0, 0, 0}, 300, 1.0));
  return fs;
}

struct Rendered {
  FrameImage image;
  RenderStats stats;
};

Rendered render(const SceneSpec& fs, const RenderSettings& rs, ShotResources& res, SampleMemo* memo) {
  const Scene scene = build_scene(fs, rs.width, rs.height, res);
  std::vector<int> rows(static_cast<std::size_t>(rs.height));
  std::iota(rows.begin(), rows.end(), 0);
  Rendered r{make_frame(rs), {}};
  r.stats = render_rows(scene, rs, rows, r.image, memo);
  return r;
}

TEST(SampleMemo, AFrameFromKeptSamplesIsTheFrameTracedAfresh) {
  const RenderSettings rs{48, 27, 2, true};
  ShotResources res;
  SampleMemo memo(rs);
  const Rendered first = render(dihole_at(100), rs, res, &memo);
  EXPECT_EQ(first.stats.reused, 0);
  const Rendered reused = render(dihole_at(106), rs, res, &memo);
  const Rendered fresh = render(dihole_at(106), rs, res, nullptr);
  // The sphere moved between the frames: stale samples near it would show.
  EXPECT_NE(first.image.rgb, fresh.image.rgb);
  EXPECT_EQ(reused.image.rgb, fresh.image.rgb);
  ASSERT_EQ(reused.image.layers.size(), fresh.image.layers.size());
  for (std::size_t k = 0; k < fresh.image.layers.size(); ++k) {
    const auto& a = reused.image.layers[k].values;
    const auto& b = fresh.image.layers[k].values;
    if (std::string(fresh.image.layers[k].name) != "hit.t") {
      EXPECT_EQ(a, b) << fresh.image.layers[k].name;
      continue;
    }
    // hit.t is the end's time minus the observer's: the same interval,
    // summed from another start, to rounding.
    for (std::size_t p = 0; p < a.size(); ++p) EXPECT_NEAR(a[p], b[p], 1e-5 * (1.0 + std::abs(b[p])));
  }
  // Most rays miss the sphere's path and were reused; those near it traced.
  EXPECT_GT(reused.stats.reused, fresh.stats.rays / 4);
  EXPECT_GT(reused.stats.rays, 0);
  EXPECT_EQ(reused.stats.rays + reused.stats.reused, fresh.stats.rays);
}

// A ray that passed near the sphere's path but clear of the sphere is kept
// for as long as the sphere cannot reach it: a frame a moment later reuses
// more than one much later, and is still the frame traced afresh.
TEST(SampleMemo, RaysNearThePathAreReusedWhileTheSphereCannotReachThem) {
  const RenderSettings rs{48, 27, 2, false};
  ShotResources res;
  SampleMemo soon_memo(rs), late_memo(rs);
  // Windows are worked out from a still stretch's second frame on (its
  // first may be a pan's: sample_memo.hpp, Row::continues).
  for (SampleMemo* memo : {&soon_memo, &late_memo})
    for (const double t : {99.75, 100.0}) render(dihole_at(t), rs, res, memo);
  const Rendered soon = render(dihole_at(100.25), rs, res, &soon_memo);
  const Rendered late = render(dihole_at(130), rs, res, &late_memo);
  EXPECT_EQ(soon.image.rgb, render(dihole_at(100.25), rs, res, nullptr).image.rgb);
  EXPECT_EQ(late.image.rgb, render(dihole_at(130), rs, res, nullptr).image.rgb);
  EXPECT_GT(soon.stats.reused, late.stats.reused);
  EXPECT_GT(soon.stats.rays, 0);  // those that enter the sphere's tube are traced again
}

TEST(SampleMemo, AnotherSceneReusesNothing) {
  const RenderSettings rs{32, 18, 2, false};
  ShotResources res;
  SampleMemo memo(rs);
  render(dihole_at(100), rs, res, &memo);
  SceneSpec turned = dihole_at(100);
  turned.camera.get<PinholeCamera::Params>().yaw = 1e-9;  // a hair's turn: every ray is another
  const Rendered r = render(turned, rs, res, &memo);
  EXPECT_EQ(r.stats.reused, 0);
  EXPECT_EQ(r.image.rgb, render(turned, rs, res, nullptr).image.rgb);
  // A flat, empty scene (a hold) reuses every sample of the next frame.
  SceneSpec flat;
  flat.observer = StaticObserver::Params{{0, 0, 40, 0}};
  render(flat, rs, res, &memo);
  std::get<StaticObserver::Params>(flat.observer).position[0] = 50;
  const Rendered hold = render(flat, rs, res, &memo);
  EXPECT_EQ(hold.stats.rays, 0);
  EXPECT_GT(hold.stats.reused, 0);
}

TEST(SampleMemo, RaysNearASphereAtRestAreTracedAgain) {
  // The sphere test works in absolute coordinate time, so a later frame's
  // samples that enter the tube round a sphere at rest may round
  // differently: they are traced.
  const RenderSettings rs{32, 18, 2, false};
  ShotResources res;
  SampleMemo memo(rs);
  auto held = [](double t) {
    SceneSpec fs = dihole_at(t);
    fs.objects[0].get<Sphere::Params>().placement.at = Vec4{0, 5, 0, 0};
    return fs;
  };
  render(held(100), rs, res, &memo);
  const Rendered later = render(held(1000), rs, res, &memo);
  EXPECT_GT(later.stats.rays, 0);
  EXPECT_GT(later.stats.reused, later.stats.rays);
  EXPECT_EQ(later.image.rgb, render(held(1000), rs, res, nullptr).image.rgb);
}


// The memo's promise, one ray of the paper's dihole shot (frames 514 and
// 515 at 640 x 360, 0.335 M apart, the sphere swinging through the holes'
// field): a ray clear of the sphere, whose reuse window covers the next
// frame, sees the same in that frame.  It passes 1.3 M from the centre; the
// sphere's rest slices put no point of it near the ray.  The simultaneity
// search there has no root near the ray point's time, and once took the
// centre wherever its unsettled search ended (the swinging centre passes
// near again 11 M later): a false hit, a sliver of sphere in the sky of the
// frame traced afresh but not of the one reusing the ray.
TEST(SampleMemo, ARayClearOfTheSwingingSphereStaysClearForItsWindow) {
  Shot shot(std::string(LIGHTCONE_SOURCE_DIR) + "/shots/dihole.lua");
  ShotResources res;
  HitRecord seen[2];
  double time[2];
  for (int k = 0; k < 2; ++k) {
    const Scene scene = build_scene(shot.frame(514 + k), 640, 360, res);
    const auto& sc = scene_get<Dihole>(scene);
    const RayStart start{&sc.eye, unit3(sc.camera.direction(187.75, 196.75))};
    seen[k].reuse_window = std::numeric_limits<float>::infinity();  // work it out
    trace_records(sc, std::span<const RayStart>(&start, 1), std::span<HitRecord>(&seen[k], 1));
    time[k] = sc.eye.time;
  }
  ASSERT_GT(static_cast<double>(seen[0].reuse_window), time[1] - time[0]);
  EXPECT_EQ(seen[0].kind, HitKind::sky);
  EXPECT_EQ(seen[1].kind, seen[0].kind);
}

}  // namespace
}  // namespace lc
