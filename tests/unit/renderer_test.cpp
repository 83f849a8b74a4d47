// Rendering against figures known independently: the shadow size of a
// Schwarzschild hole, the exact flat-space projection of the disk, the
// rotational symmetry of a disk seen along the axis, the angular size of a
// sphere in flat space, and identical images for any thread count.

#include <random>

#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole.hpp"
#include "core/constants.hpp"
#include "objects/disk.hpp"
#include "objects/objects.hpp"
#include "objects/sphere.hpp"
#include "render/accuracy.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "render/scene_visit.hpp"
#include "render/trace.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"
#include "test_scenes.hpp"

namespace lc {
namespace {

SceneSpec kerr_scene(double M, double a, double r, double theta_deg, double fov, bool disk) {
  SceneSpec fs;
  fs.spacetime = Kerr(M, a);
  fs.observer = StaticObserver::Params{{0, r, theta_deg * degree, 0}};
  fs.camera.get<PinholeParams>().fov = fov;
  if (disk) fs.objects.push_back(Disk::Params{6, 15, 9, 24});
  return fs;
}

RaySample sample_at(const Scene& scene, double px, double py) {
  return trace_image_point(scene, px, py);
}

// Every pixel-centre sample of a W x H image of `fs`, traced with `chart`
// at `tolerance`.
std::vector<RaySample> samples(const SceneSpec& fs, int W, int H, KerrChart chart, double tolerance) {
  ShotResources res;
  RayOptions o;
  o.kerr_chart = chart;
  o.control.rtol = o.control.atol = tolerance;
  o.control.h_min = 1e-14;
  const Scene scene = build_scene(fs, W, H, res, o);
  std::vector<RaySample> out;
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) out.push_back(sample_at(scene, i + 0.5, j + 0.5));
  return out;
}

TEST(Renderer, KerrFastPathAgreesWithKerrSchild) {
  // The Boyer–Lindquist–Mino integrator at tolerance 1e-12 against the
  // Kerr–Schild Hamiltonian at 1e-14, on the bench camera (a = 0.9 from
  // r = 30 at 80 deg: rays that graze the photon orbit, cross the disk plane
  // several times or fall in) and from on the spin axis (where the BL path
  // starts L = 0 rays along their own meridian).  Two independent
  // formulations.  Measured convergence (docs/performance.md): a
  // second-order image (one that crossed the plane twice) converges in
  // Kerr–Schild to ~1e-7 M at 1e-14 and in BL to ~1e-9 at 1e-12, direct
  // and first-order images far better; the bounds leave a factor ~5.
  for (const double theta : {80.0, 0.0}) {
    const SceneSpec fs = kerr_scene(1, 0.9, 30, theta, 40, true);
    const auto ks = samples(fs, 40, 40, KerrChart::kerr_schild, 1e-14);
    const auto bl = samples(fs, 40, 40, KerrChart::boyer_lindquist_mino, 1e-12);
    const AccuracyReport a = compare_samples(ks, bl, fs);
    EXPECT_EQ(a.kind_mismatches, 0) << "theta " << theta;
    EXPECT_EQ(a.cell_mismatches, 0) << "theta " << theta;
    EXPECT_GT(a.disk_pixels, 100) << "theta " << theta;
    EXPECT_LT(a.dr_p99, 1e-7) << "theta " << theta;
    EXPECT_LT(a.dr_max, 5e-7) << "theta " << theta;
    EXPECT_LT(a.dphi_max, 5e-7) << "theta " << theta;
    RecordProperty(theta == 0 ? "axis_dr_max" : "inclined_dr_max", std::to_string(a.dr_max));
    double worst_t = 0;
    for (std::size_t k = 0; k < ks.size(); ++k) {
      if (ks[k].hit.kind == Disk::hit_kind || ks[k].hit.kind == HitKind::horizon)
        worst_t = std::max(worst_t, std::abs(ks[k].hit.t - bl[k].hit.t));
      EXPECT_EQ(ks[k].hit.order, bl[k].hit.order) << "pixel " << k;
      if (ks[k].hit.kind == HitKind::sky) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(ks[k].color[c], bl[k].color[c], 1e-6) << "pixel " << k;
      }
    }
    // hit.t of disk and horizon events (scene time, docs/layers.md): the two
    // formulations agree to 1.3e-4 M (measured), the Mino time's rate having
    // a kink at radial turning points (kerr_mino.hpp).
    EXPECT_LT(worst_t, 5e-4) << "theta " << theta;
  }
}

TEST(Renderer, SchwarzschildShadowAngularRadius) {
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
  ASSERT_EQ(sample_at(scene, lo, 0.5).hit.kind, HitKind::horizon);
  ASSERT_EQ(sample_at(scene, hi, 0.5).hit.kind, HitKind::sky);
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (sample_at(scene, mid, 0.5).hit.kind == HitKind::horizon ? lo : hi) = mid;
  }
  const double angle = std::atan((2 * lo / W - 1) * std::tan(15 * degree)) / degree;
  EXPECT_NEAR(angle, expected, 2e-4);  // the integrator decides the edge to ~1e-6 rad
  // And in pixel terms: within one pixel of the predicted edge.
  const double px = W / 2.0 * (1 + std::tan(expected * degree) / std::tan(15 * degree));
  EXPECT_NEAR(lo, px, 1.0);
}

TEST(Renderer, FlatSpaceDiskIsTheExactProjection) {
  // M = 0: each pixel's disk hit is where the straight line from the camera
  // meets z = 0.  At tolerance 1e-10 to 1e-7 relative (the formulation is
  // exact); at the production tolerance, chosen by image error, to 1e-4 M
  // at worst (the bench's standard is a 99th percentile of 1e-5 M).
  const int W = 48, H = 48;
  for (const auto& [tolerance, bound] : {std::pair{1e-10, 1e-7}, std::pair{default_ray_tolerance, 1e-5}}) {
    ShotResources res;
    const SceneSpec fs = kerr_scene(0, 0, 30, 70, 50, true);
    RayOptions o;
    o.control.rtol = o.control.atol = tolerance;
    const Scene scene = build_scene(fs, W, H, res, o);
    const Vec3 cam = {30 * std::sin(70 * degree), 0, 30 * std::cos(70 * degree)};
    const PinholeCamera camera(fs.camera.get<PinholeParams>(), W, H);
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
          EXPECT_EQ(s.hit.kind, HitKind::sky);
          continue;
        }
        const double k = -cam[2] / d[2];
        const double x = cam[0] + k * d[0], y = cam[1] + k * d[1];
        const double r = std::hypot(x, y);
        if (r < 6 || r > 15) {
          EXPECT_EQ(s.hit.kind, HitKind::sky) << i << "," << j;
          continue;
        }
        ++disk_pixels;
        ASSERT_EQ(s.hit.kind, Disk::hit_kind) << i << "," << j;
        EXPECT_NEAR(s.hit.r, r, bound * r) << "tolerance " << tolerance;
        double phi = std::atan2(y, x);
        if (phi < 0) phi += two_pi;
        EXPECT_NEAR(std::remainder(s.hit.phi - phi, two_pi), 0.0, bound) << "tolerance " << tolerance;
        EXPECT_EQ(s.hit.order, 0);
      }
    EXPECT_GT(disk_pixels, 200);
  }
}

TEST(Renderer, DiskSeenAlongTheAxisIsRotationallySymmetric) {
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

TEST(Renderer, ObserverOnTheSouthAxisSeesTheNorthViewUpsideDown) {
  // Reflection through the equatorial plane maps Kerr (a kept), the disk
  // and an observer on the axis at theta = 0 onto one at theta = 180 deg,
  // and the camera's up (-e_theta) onto its opposite: the image is the same
  // with its rows in reverse order.  180 deg is pi rounded, whose sine is
  // 1.2e-16, not 0: the fast path must still start the rays on the axis.
  const int W = 24;
  ShotResources res;
  RenderSettings rs{W, W, 1, true};
  const FrameImage north = render_frame(build_scene(kerr_scene(1, 0.9, 30, 0, 60, true), W, W, res), rs, 1);
  for (const double theta : {180.0, -180.0}) {
    for (const bool zamo : {false, true}) {
      SceneSpec fs = kerr_scene(1, 0.9, 30, theta, 60, true);
      if (zamo) fs.observer = Zamo::Params{std::get<StaticObserver::Params>(fs.observer).position};
      RenderStats stats;
      const FrameImage south = render_frame(build_scene(fs, W, W, res), rs, 1, &stats);
      EXPECT_EQ(stats.gave_up, 0) << "theta " << theta;
      int disk = 0;
      for (int j = 0; j < W; ++j)
        for (int i = 0; i < W; ++i) {
          const int p = j * W + i, q = (W - 1 - j) * W + i;
          ASSERT_EQ(north.layers[0].values[p], south.layers[0].values[q]) << "theta " << theta << " pixel " << i << "," << j;
          if (north.layers[0].values[p] == 1.0f) {
            ++disk;
            EXPECT_NEAR(north.layers[1].values[p], south.layers[1].values[q], 1e-4f * north.layers[1].values[p]);
          }
        }
      EXPECT_GT(disk, 50) << "theta " << theta;
    }
  }
}

// The centre ray of a 1 x 1 image of `fs` looking straight along forward,
// traced with `chart`.
RaySample centre_ray(SceneSpec fs, double yaw, KerrChart chart) {
  fs.camera.get<PinholeParams>().yaw = yaw;
  ShotResources res;
  RayOptions o;
  o.kerr_chart = chart;
  return sample_at(build_scene(fs, 1, 1, res, o), 0.5, 0.5);
}

TEST(Renderer, LayersPutSkyAndHorizonEventsWhereAndWhenRadialRaysAre) {
  // docs/layers.md: hit.r and hit.t are the event where the ray ended, t
  // minus the observer's.  Radial rays have it in closed form: in Kerr along
  // the spin axis (Carter's K = a^2 E^2) dt/dr = (r^2 + a^2)/Delta, so
  // t = r + T(r), T' = 2Mr/Delta (Kerr::time_shift of the ingoing chart);
  // in the dihole along the y axis (between the holes, by symmetry) and
  // along the z axis, dt = U^2 ds.  Backwards from the camera the event is
  // earlier: t < 0 whichever way the ray goes.  Tolerance 1e-5 M near the
  // holes; far out 2e-6 of t: the production tolerance 5e-8, relaxed
  // 100-fold in free flight, leaves the Hamiltonian path's t ~1e-6 off at
  // 1000 M (the Kerr–Mino path's is exact there, see kerr_mino.hpp).
  for (const double a : {0.0, 0.9}) {
    const Kerr hole(1, a, KerrSchildSense::ingoing);
    auto light_time = [&](double r) { return r + hole.time_shift(r); };
    SceneSpec fs = kerr_scene(1, a, 30, a == 0.0 ? 90 : 0, 60, false);
    for (const KerrChart chart : {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild}) {
      const RaySample away = centre_ray(fs, 180, chart);
      ASSERT_EQ(away.hit.kind, HitKind::sky) << "a " << a;
      EXPECT_GE(away.hit.r, default_escape_radius * (1 - 1e-12)) << "a " << a;
      EXPECT_NEAR(away.hit.t, -(light_time(away.hit.r) - light_time(30)), 2e-6 * std::abs(away.hit.t))
          << "a " << a << " chart " << int(chart);
      EXPECT_LT(away.hit.t, -(away.hit.r - 30)) << "light is not faster than in flat space";
      const RaySample in = centre_ray(fs, 0, chart);
      ASSERT_EQ(in.hit.kind, HitKind::horizon) << "a " << a;
      EXPECT_LE(in.hit.r, hole.capture_radius() * (1 + 1e-12)) << "a " << a;  // located to 1e-12
      EXPECT_GT(in.hit.r, hole.horizon_radius()) << "a " << a;
      EXPECT_NEAR(in.hit.t, -(light_time(30) - light_time(in.hit.r)), 1e-5) << "a " << a << " chart " << int(chart);
    }
  }
  // The paper's dihole (m = 0.4 at z = +-1).  Along y through the middle:
  // U = 1 + 2m / sqrt(y^2 + 1); the ray towards the holes passes between
  // them and escapes on the far side.
  const double m = 0.4;
  auto along_y = [&](double y) { return y + 4 * m * std::asinh(y) + 4 * m * m * std::atan(y); };
  SceneSpec di;
  di.spacetime = Dihole(m, m, 1.0);
  di.observer = StaticObserver::Params{{0, 0, 80, 0}};
  const RaySample away = centre_ray(di, 180, KerrChart::kerr_schild);
  ASSERT_EQ(away.hit.kind, HitKind::sky);
  EXPECT_NEAR(away.hit.t, -(along_y(away.hit.r) - along_y(80)), 2e-6 * std::abs(away.hit.t));
  const RaySample through = centre_ray(di, 0, KerrChart::kerr_schild);
  ASSERT_EQ(through.hit.kind, HitKind::sky);
  EXPECT_NEAR(through.hit.t, -(along_y(80) + along_y(through.hit.r)), 2e-6 * std::abs(through.hit.t));
  // Down the z axis into the upper hole: U = 1 + m/(z - 1) + m/(z + 1).
  auto along_z = [&](double z) {
    return z - m * m / (z - 1) - m * m / (z + 1) + 2 * m * std::log(z - 1) + 2 * m * std::log(z + 1) +
           m * m * std::log((z - 1) / (z + 1));
  };
  di.observer = StaticObserver::Params{{0, 0, 0, 80}};
  const RaySample down = centre_ray(di, 0, KerrChart::kerr_schild);
  ASSERT_EQ(down.hit.kind, HitKind::horizon);
  EXPECT_LT(down.hit.r, 1.0 + m);
  EXPECT_NEAR(down.hit.t, -(along_z(80) - along_z(down.hit.r)), 1e-5);
  // Flat space: t = -distance.
  SceneSpec flat = di;
  flat.spacetime = Minkowski{};
  const RaySample straight = centre_ray(flat, 180, KerrChart::kerr_schild);
  ASSERT_EQ(straight.hit.kind, HitKind::sky);
  EXPECT_NEAR(straight.hit.t, -(straight.hit.r - 80), 1e-9);
}

// Scenes for every path of the ray loop: flat space, Kerr in the fast
// path, Kerr with a sphere (Kerr–Schild), the dihole with a sphere.
std::vector<std::pair<std::string, SceneSpec>> scenes_of_every_path() {
  std::vector<std::pair<std::string, SceneSpec>> out;
  SceneSpec flat;
  flat.spacetime = Minkowski{};
  flat.observer = StaticObserver::Params{{0, 0, 30, 5}};
  flat.objects.push_back(test::falling_sphere(flat.spacetime, {0, 3, 0, 0}, {0, 0.1, 0}, 100, 1.0));
  out.emplace_back("minkowski", flat);
  out.emplace_back("kerr bl-mino", kerr_scene(1, 0.9, 30, 80, 40, true));
  SceneSpec kerr_sphere = kerr_scene(1, 0.9, 30, 80, 40, true);
  kerr_sphere.objects.push_back(test::falling_sphere(kerr_sphere.spacetime, {0, 10, 90 * degree, 0}, {0, 0, 0.3}, 60, 1.0));
  out.emplace_back("kerr kerr-schild", kerr_sphere);
  SceneSpec di;
  di.spacetime = Dihole(0.4, 0.4, 1.0);
  di.observer = StaticObserver::Params{{90, 0, 40, 0}};
  di.camera.get<PinholeParams>().fov = 30;
  di.objects.push_back(test::falling_sphere(di.spacetime, {0, 5, 0, 0}, {0, 0, 0}, 300, 1.0));
  out.emplace_back("dihole", di);
  return out;
}

TEST(Renderer, LanesGiveWhatOneRayGives) {
  // The renderer traces rays lane_count at a time (render/trace.hpp) and
  // `lightcone trace` one alone: the same arithmetic, written once for
  // both.  (1) A ray's sample must not depend on the rays beside it in its
  // batch or on the lane it lands in: frames reusing samples rely on that
  // to the bit (render/sample_memo.hpp).  (2) One ray alone (doubles) and
  // in lanes (vectors) agree in hit kind, and in r, phi and t to 1e-6
  // relative: the compiler contracts multiply-adds into fused ones
  // differently in scalar and vector code (~1e-16), and the step
  // controller can turn that into a different last step (~1e-8 measured).
  for (const auto& [name, fs] : scenes_of_every_path()) {
    const int W = 24, H = 12;
    ShotResources res;
    const Scene scene = build_scene(fs, W, H, res);
    visit_scene(
        [&](const auto& sc) {
          std::vector<Vec3> dirs;
          for (int j = 0; j < H; ++j)
            for (int i = 0; i < W; ++i) dirs.push_back(sc.camera.direction(i + 0.5, j + 0.5));
          std::vector<RaySample> batch(dirs.size());
          trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(batch));
          int hits = 0;
          for (std::size_t k = 0; k < dirs.size(); ++k) {
            RaySample alone;
            trace_batch(sc, std::span<const Vec3>(&dirs[k], 1), std::span<RaySample>(&alone, 1));
            ASSERT_EQ(alone.hit.kind, batch[k].hit.kind) << name << " ray " << k;
            EXPECT_EQ(alone.hit.r, batch[k].hit.r) << name << " ray " << k;
            EXPECT_EQ(alone.hit.phi, batch[k].hit.phi) << name << " ray " << k;
            EXPECT_EQ(alone.hit.t, batch[k].hit.t) << name << " ray " << k;
            EXPECT_EQ(alone.color, batch[k].color) << name << " ray " << k;
            const RaySample one = trace_sample(sc, dirs[k]);
            ASSERT_EQ(one.hit.kind, batch[k].hit.kind) << name << " ray " << k;
            EXPECT_NEAR(one.hit.r, batch[k].hit.r, 1e-6 * std::abs(batch[k].hit.r)) << name << " ray " << k;
            EXPECT_NEAR(one.hit.t, batch[k].hit.t, 1e-6 * (1 + std::abs(batch[k].hit.t))) << name << " ray " << k;
            hits += batch[k].hit.kind == Sphere::hit_kind || batch[k].hit.kind == Disk::hit_kind;
          }
          EXPECT_GT(hits, 0) << name << ": no ray met an object";
        },
        scene);
  }
}

TEST(Renderer, SphereInFlatSpaceHasItsAngularSize) {
  SceneSpec fs;
  fs.spacetime = Dihole(0.0, 0.0, 1.0);
  fs.observer = StaticObserver::Params{{0, 0, 80, 0}};
  fs.camera.get<PinholeParams>().fov = 12;
  Sphere::Params sp;
  sp.radius = 1.0;
  sp.placement.at = Vec4{0, 5, 0, 0};
  fs.objects.push_back(sp);
  ShotResources res;
  const int W = 400;
  const Scene scene = build_scene(fs, W, 1, res);
  // The sphere's centre is at angle atan(5/80) to the right of forward
  // (forward = -y, right = e_phi = -x at phi = 90 deg... the observer at
  // (0, 80, 0) has e_phi = (-1, 0, 0), so +x is to the left).
  const double t = std::tan(6 * degree);
  auto px_of = [&](double angle) { return W / 2.0 * (1 + std::tan(angle) / t); };
  const double centre = std::atan2(-5.0, 80.0), half = std::asin(1.0 / std::hypot(5.0, 80.0));
  EXPECT_EQ(sample_at(scene, px_of(centre), 0.5).hit.kind, Sphere::hit_kind);
  // Bisect the right edge (limb) of the disc in the image.
  double lo = px_of(centre), hi = px_of(centre + 2 * half);
  ASSERT_EQ(sample_at(scene, hi, 0.5).hit.kind, HitKind::sky);
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (sample_at(scene, mid, 0.5).hit.kind == Sphere::hit_kind ? lo : hi) = mid;
  }
  // The limb is where the line of sight is tangent: angle centre + half.
  EXPECT_NEAR(std::atan((2 * lo / W - 1) * t), centre + half, 1e-6);
}

// Angular extent of the object along a line of the image through (cx, cy)
// in direction (dx, dy): bisects both edges from a point inside.
double extent(const Scene& scene, double cx, double cy, double dx, double dy, double reach) {
  double edges[2];
  for (int side = 0; side < 2; ++side) {
    const double sgn = side == 0 ? 1.0 : -1.0;
    double lo = 0.0, hi = reach;
    for (int it = 0; it < 50; ++it) {
      const double mid = 0.5 * (lo + hi);
      (sample_at(scene, cx + sgn * mid * dx, cy + sgn * mid * dy).hit.kind == Sphere::hit_kind ? lo : hi) = mid;
    }
    edges[side] = lo;
  }
  return edges[0] + edges[1];
}

// A scene of one sphere of radius `radius` released from (5, 0, 0) at
// `velocity` in `spacetime`, seen from far off: for the sphere's own tests.
Scene falling_sphere_scene(const Spacetime& spacetime, const Vec3& velocity, double radius, ShotResources& res) {
  SceneSpec fs;
  fs.spacetime = spacetime;
  fs.observer = StaticObserver::Params{{200, 0, 80, 0}};
  fs.objects.push_back(test::falling_sphere(fs.spacetime, {0, 5, 0, 0}, velocity, 200, radius));
  return build_scene(fs, 8, 8, res);
}

TEST(Renderer, SphereSimultaneityIsSolvedNearAMovingSphere) {
  // The sphere of the paper's dihole sequence swings through the holes at
  // up to ~0.8 c.  A point X on its surface, on the slice simultaneous with
  // its centre at C (g(X - C, u) = 0, the local linearisation of docs/architecture.md), must
  // lead back to that C from X's own time: to 1e-6 M, far below a pixel
  // (~0.02 M at the sphere in the film).  (A wrong-signed Newton step once
  // doubled the error at each iteration instead.)
  ShotResources res;
  const Scene scene = falling_sphere_scene(Dihole(0.4, 0.4, 1.0), {0, 0, 0}, 1.0, res);
  const auto& sc = scene_get<Dihole>(scene);
  const Sphere& sphere = std::get<std::vector<Sphere>>(sc.objects->lists).front();
  double worst = 0.0;
  for (double t = 30.0; t < 150.0; t += 0.37) {
    Vec4 C, u;
    sphere.centre(t, C, u);
    const Mat4 g = sc.spacetime.metric(C);
    for (const Vec4& dir : {Vec4{0, 1.0, 0.3, -0.2}, Vec4{0, -0.4, 0.8, 0.6}, Vec4{0, 0.2, -0.4, -1.0}}) {
      // Project onto the slice, scale to the surface (|xi| = R = 1).
      Vec4 xi = dir + contract(g, dir, u) * u;
      xi = (1.0 / std::sqrt(contract(g, xi, xi))) * xi;
      const Vec4 X = C + xi;
      Vec4 Cs, us;
      detail::MetricAt<Dihole> gs;
      detail::sphere_simultaneous_time(sc.spacetime, sphere, X, X[0], Cs, us, gs);
      for (int m = 0; m < 4; ++m) worst = std::max(worst, std::abs(Cs[m] - C[m]));
    }
  }
  EXPECT_LT(worst, 1e-6);
}

// The tube's radius holds the sphere: a point of its surface (on the rest
// space through its centre event C, as the sphere test defines it) is, in
// coordinates, at most tube_radius() from where the centre is at the
// point's own time.  Checked on 200 surface directions at times off the
// worldline's table, for the paper's dihole sphere (through the holes at
// up to ~0.77 c) and for one moving at 0.6 c in flat space.  The bound must
// also be tight: the paper's sphere reaches at least 90% of it, and fits in
// 1.1 R (the old fixed tube was 2 R; what its size costs: docs/performance.md,
// change 35).
template <class S>
double farthest_surface_point(const S& st, const Sphere& sphere, double t0, double t1) {
  double seen = 0.0;
  constexpr int n = 200;
  for (double t = t0; t < t1; t += 0.173) {
    Vec4 C, u;
    sphere.centre(t, C, u);
    const Tetrad f = orthonormalize(st.metric(C), {u, Vec4{0, 1, 0, 0}, Vec4{0, 0, 1, 0}, Vec4{0, 0, 0, 1}}, "test");
    for (int i = 0; i < n; ++i) {
      // Fibonacci directions: even over the unit sphere.
      const double z = 1.0 - (2.0 * i + 1.0) / n, rho = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
      const Vec4 X = C + sphere.radius * (rho * std::cos(phi) * f.e[1] + rho * std::sin(phi) * f.e[2] + z * f.e[3]);
      Vec4 Cx, ux;
      sphere.centre(X[0], Cx, ux);
      seen = std::max(seen, std::hypot(X[1] - Cx[1], X[2] - Cx[2], X[3] - Cx[3]));
    }
  }
  return seen;
}

TEST(Renderer, SphereTubeHoldsTheSphere) {
  {
    ShotResources res;
    const Scene scene = falling_sphere_scene(Dihole(0.4, 0.4, 1.0), {0, 0, 0}, 1.0, res);
    const auto& sc = scene_get<Dihole>(scene);
    const Sphere& sphere = std::get<std::vector<Sphere>>(sc.objects->lists).front();
    const double seen = farthest_surface_point(sc.spacetime, sphere, -3.0, 230.0);
    EXPECT_LE(seen, sphere.tube_radius());
    EXPECT_GT(seen, 0.9 * sphere.tube_radius());
    EXPECT_LT(sphere.tube_radius(), 1.1);
  }
  {
    ShotResources res;
    const Scene scene = falling_sphere_scene(Minkowski{}, {-0.6, 0, 0}, 2.0, res);
    const auto& sc = scene_get<Minkowski>(scene);
    const Sphere& sphere = std::get<std::vector<Sphere>>(sc.objects->lists).front();
    // Once moving, the contracted sphere reaches R across its motion (to
    // 1e-5: the directions pass within ~0.005 rad of that circle) ...
    EXPECT_NEAR(farthest_surface_point(sc.spacetime, sphere, 10.0, 150.0), 2.0, 1e-5);
    // ... and round its release, standing still before it, up to the
    // release speed times its rest space's tilt (gamma beta R) more.
    EXPECT_LE(farthest_surface_point(sc.spacetime, sphere, -10.0, 10.0), sphere.tube_radius());
    EXPECT_NEAR(sphere.tube_radius(), 1.05 * (2.0 + 0.6 * 0.75 * 2.0), 1e-9);
  }
}

TEST(Renderer, MovingSphereKeepsACircularOutline) {
  // Penrose (1959), Terrell (1959): a sphere moving at any speed is seen with
  // a circular outline, although in the frame of the observer it is
  // flattened by 1/gamma = 0.8 at v = 0.6.  This needs the sphere taken on its
  // own simultaneity slice and light-travel time along each ray: a renderer
  // that got either wrong would see an ellipse.
  SceneSpec fs;
  fs.spacetime = Minkowski{};
  fs.observer = StaticObserver::Params{{150, 0, 60, 0}};  // at t = 150, on the y axis, looking at the origin
  fs.camera.get<PinholeParams>().fov = 90;
  fs.objects.push_back(test::falling_sphere(Minkowski{}, {0, -70, 0, 0}, {0.6, 0, 0}, 300, 3.0));
  ShotResources res;
  const int W = 600, H = 600;
  const Scene scene = build_scene(fs, W, H, res);
  // Find the sphere on the middle row (it moves in the plane z = 0).
  double first = -1, last = -1;
  for (int i = 0; i < W; ++i)
    if (sample_at(scene, i + 0.5, H / 2.0).hit.kind == Sphere::hit_kind) {
      if (first < 0) first = i + 0.5;
      last = i + 0.5;
    }
  ASSERT_GT(first, 0) << "the sphere is not in view";
  const double cx0 = 0.5 * (first + last);
  const double width = extent(scene, cx0, H / 2.0, 1, 0, 200);
  // Re-centre horizontally on the measured edges, then measure vertically.
  const double height = extent(scene, cx0, H / 2.0, 0, 1, 200);
  EXPECT_GT(width, 10.0);  // pixels: big enough to measure
  // The outline is a circle to within the pinhole projection's distortion
  // off-axis (the sphere sits ~20 deg off-centre: tan-projection stretches
  // horizontally by 1/cos^2 vs 1/cos, about 6%); compare against the same
  // measurement of a sphere at rest at the same apparent place instead.
  SceneSpec still = fs;
  // Apparent position: straight back along the centre ray of the moving image.
  const Vec3 n = scene_get<Minkowski>(scene).camera.direction(cx0, H / 2.0);
  const Tetrad rest = static_polar_tetrad(Minkowski{}, std::get<StaticObserver::Params>(fs.observer).position);
  double dir[3] = {0, 0, 0};
  for (int k = 0; k < 3; ++k)
    for (int leg = 0; leg < 3; ++leg) dir[k] += n[leg] * rest.e[leg + 1][k + 1];
  const double dist = 60.0 / std::abs(dir[1]);  // reach the plane y = 0
  still.objects[0].get<Sphere::Params>().placement.at = Vec4{0, dist * dir[0], 60 + dist * dir[1], dist * dir[2]};
  ShotResources res2;
  const Scene still_scene = build_scene(still, W, H, res2);
  const double w0 = extent(still_scene, cx0, H / 2.0, 1, 0, 200);
  const double h0 = extent(still_scene, cx0, H / 2.0, 0, 1, 200);
  EXPECT_NEAR(width / height, w0 / h0, 0.01) << "moving " << width << "x" << height << ", at rest " << w0 << "x" << h0;
}

TEST(Renderer, MovingObserverSeesAberration) {
  // An observer moving at v towards where it looks sees a direction that is
  // at angle theta from the motion in the rest frame at theta' with
  // cos theta' = (cos theta + v) / (1 + v cos theta) — through its boosted
  // tetrad alone.  Flat space, observer at the origin moving along -x (its
  // forward, the boosted -e_x leg); straight rays, so the escape point's
  // direction from the origin is the rest-frame direction.
  SceneSpec fs;
  fs.spacetime = Minkowski{};
  WorldlineSpec w;
  w.spacetime = Minkowski{};
  w.start = {0, 0, 0, 0};
  w.velocity = {-0.5, 0, 0};
  w.duration = 10;
  w.where = "test";
  FreeFall::Params ride;
  ride.worldline = w;
  ride.proper_time = 0;
  fs.observer = ride;
  fs.camera.get<PinholeParams>().fov = 120;
  ShotResources res;
  const int W = 64;
  const Scene scene = build_scene(fs, W, 1, res);
  const auto& sc = scene_get<Minkowski>(scene);
  for (double px : {40.5, 50.5, 60.5}) {
    const Vec3 n = sc.camera.direction(px, 0.5);
    const double cos_seen = n[0] * -1.0;  // angle from forward (-leg 1) in the moving frame
    const RaySample s = sample_at(scene, px, 0.5);
    ASSERT_EQ(s.hit.kind, HitKind::sky);
    const double dx = s.hit.end[1], dy = s.hit.end[2], dz = s.hit.end[3];
    const double cos_rest = -dx / std::sqrt(dx * dx + dy * dy + dz * dz);  // angle from -x
    EXPECT_NEAR(cos_seen, (cos_rest + 0.5) / (1 + 0.5 * cos_rest), 1e-9) << px;
  }
}

TEST(Renderer, ThreadCountDoesNotChangeTheImage) {
  const int W = 24, H = 18;
  ShotResources res;
  RenderSettings rs{W, H, 2, true};
  const Scene scene = build_scene(kerr_scene(1, 0.9, 30, 80, 40, true), W, H, res);
  const FrameImage one = render_frame(scene, rs, 1);
  const FrameImage three = render_frame(scene, rs, 3);
  EXPECT_EQ(one.rgb, three.rgb);
  for (std::size_t k = 0; k < one.layers.size(); ++k) EXPECT_EQ(one.layers[k].values, three.layers[k].values);
}

TEST(Renderer, AdaptiveSupersamplingRefinesWhereSamplesDiffer) {
  // 2x2 adaptive against the full grid on the disk scene: one sample per
  // pixel where it agrees with its row neighbours' (the pixel is then flat
  // to the threshold), the full grid at the disk's and shadow's edges.
  const int W = 160, H = 120;
  ShotResources res;
  const Scene scene = build_scene(kerr_scene(1, 0.9, 30, 80, 40, true), W, H, res);
  RenderSettings full{W, H, 2, false, false}, adaptive{W, H, 2, false, true};
  RenderStats sf, sa;
  const FrameImage a = render_frame(scene, adaptive, 2, &sa);
  const FrameImage f = render_frame(scene, full, 2, &sf);
  EXPECT_EQ(sf.rays, 4L * W * H);
  EXPECT_LT(sa.rays, 3L * W * H);  // most pixels are flat (small as it is, the scene is mostly edges)
  EXPECT_GT(sa.rays, 1L * W * H);  // edges are refined
  double mean = 0;
  for (std::size_t k = 0; k < a.rgb.size(); ++k) mean += std::abs(a.rgb[k] - f.rgb[k]);
  mean /= static_cast<double>(a.rgb.size());
  RecordProperty("adaptive_rays_per_pixel", std::to_string(double(sa.rays) / (W * H)));
  RecordProperty("adaptive_mean_error", std::to_string(mean));
  EXPECT_LT(mean, 2e-3);
  // One sample per pixel has nothing to adapt: identical images.
  const FrameImage a1 = render_frame(scene, RenderSettings{W, H, 1, false, true}, 2);
  const FrameImage f1 = render_frame(scene, RenderSettings{W, H, 1, false, false}, 2);
  EXPECT_EQ(a1.rgb, f1.rgb);
}

TEST(Renderer, RefusesObserversThatCannotExist) {
  ShotResources res;
  EXPECT_THROW(build_scene(kerr_scene(1, 0.9, 1.8, 90, 40, false), 8, 8, res), std::invalid_argument);  // ergoregion
  EXPECT_THROW(build_scene(kerr_scene(1, 0.9, 1.2, 90, 40, false), 8, 8, res), std::invalid_argument);  // horizon
}

}  // namespace
}  // namespace lc
