// The light model (light/light.hpp): the paper's look leaves textures as
// they are; `shifted` picks g, its gravitational or its kinematic part, for
// the colour shift and the beaming, each switchable.  Through the renderer,
// the parts against figures known in closed form: a static observer in
// Schwarzschild sees the sky blueshifted by the lapse, all of it
// gravitational; a ZAMO on the axis of a Kerr hole sees the disk's
// gravitational shift as the ratio of the ZAMOs' lapses alpha; an observer
// running through flat space sees a kinematic shift only.

#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole_params.hpp"
#include "core/constants.hpp"
#include "light/light.hpp"
#include "objects/disk.hpp"
#include "objects/sphere.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "render/trace.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"

namespace lc {
namespace {

LightParams shifted(int color_shift, int beaming, int gravitational, int kinematic) {
  LightParams p;
  p.model = LightModel::shifted;
  p.color_shift = color_shift;
  p.beaming = beaming;
  p.gravitational = gravitational;
  p.kinematic = kinematic;
  return p;
}

TEST(Light, TheGeometricModelShowsTexturesAsTheyAre) {
  const Light geometric;
  const Color c = {0.3f, 0.6f, 0.9f};
  const SeenShift s = geometric.seen(1.7, 1.2);
  EXPECT_EQ(s.color, 1.0);
  EXPECT_EQ(s.beaming, 1.0);
  EXPECT_EQ(s.texture(c), c);
  EXPECT_FALSE(geometric.splits());
}

TEST(Light, EachSwitchPicksItsPart) {
  // g = 2 of which 1.25 gravitational: the kinematic part is 1.6.
  const auto spectra = std::make_shared<const SpectralShift>();
  struct Case {
    LightParams p;
    double color, beaming;
    bool splits;
  };
  for (const Case& c : {Case{shifted(1, 1, 1, 1), 2.0, 2.0, false}, Case{shifted(1, 1, 1, 0), 1.25, 1.25, true},
                        Case{shifted(1, 1, 0, 1), 1.6, 1.6, true}, Case{shifted(1, 1, 0, 0), 1.0, 1.0, true},
                        Case{shifted(0, 1, 1, 1), 1.0, 2.0, false}, Case{shifted(1, 0, 1, 1), 2.0, 1.0, false},
                        Case{shifted(0, 0, 1, 0), 1.0, 1.0, false}}) {
    const Light light(c.p, spectra);
    const SeenShift s = light.seen(2.0, 1.25);
    EXPECT_DOUBLE_EQ(s.color, c.color);
    EXPECT_DOUBLE_EQ(s.beaming, c.beaming);
    EXPECT_EQ(light.splits(), c.splits);
  }
  // Beaming alone scales by g^4; the colour shift alone keeps the light's
  // integral over frequency, g^-4 of the exact transformation.
  const Color c = {0.3f, 0.6f, 0.9f};
  const Color beamed = Light(shifted(0, 1, 1, 1), spectra).seen(1.1, 1.1).texture(c);
  for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(beamed[i], c[i] * static_cast<float>(std::pow(1.1, 4)));
  const Color exact = (*spectra)(c, 1.1), recoloured = Light(shifted(1, 0, 1, 1), spectra).seen(1.1, 1.1).texture(c);
  for (int i = 0; i < 3; ++i) EXPECT_FLOAT_EQ(recoloured[i], exact[i] / static_cast<float>(std::pow(1.1, 4)));
}

// Colours and samples of every pixel of a W x W image of fs.
std::vector<RaySample> samples(const SceneSpec& fs, int W, KerrChart chart = KerrChart::boyer_lindquist_mino) {
  ShotResources res;
  RayOptions o;
  o.kerr_chart = chart;
  const Scene scene = build_scene(fs, W, W, res, o);
  std::vector<RaySample> out;
  for (int j = 0; j < W; ++j)
    for (int i = 0; i < W; ++i)
      out.push_back(trace_image_point(scene, i + 0.5, j + 0.5));
  return out;
}

constexpr Color plain = {0.2f, 0.3f, 0.4f};

// Expects colour == plain * k^4, to float rounding (1e-6 relative).
void expect_beamed(const Color& c, double k, const char* what) {
  const double k4 = k * k * k * k;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(c[i], plain[i] * k4, 1e-6 * plain[i] * k4) << what << " k " << k;
}

TEST(Light, AStaticObserversSkyShiftIsAllGravitational) {
  // Schwarzschild, static observer at r = 10 (its own ZAMO): the sky's
  // g = 1 / sqrt(1 - 2M/r) is gravitational, the kinematic part 1.
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0);
  fs.observer = StaticObserver::Params{{0, 10, 60 * degree, 0}};
  fs.camera.get<PinholeParams>().fov = 120;
  std::get<CheckerSky::Params>(fs.sky).colors = {plain, plain};
  const double lapse_shift = 1 / std::sqrt(1 - 2.0 / 10);
  for (const KerrChart chart : {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild}) {
    for (const auto& [light, k] : {std::pair{shifted(0, 1, 1, 1), lapse_shift}, std::pair{shifted(0, 1, 1, 0), lapse_shift},
                                   std::pair{shifted(0, 1, 0, 1), 1.0}}) {
      fs.light = light;
      int sky = 0;
      for (const RaySample& s : samples(fs, 4, chart))
        if (s.hit.kind == HitKind::sky) {
          expect_beamed(s.color, k, "sky");
          ++sky;
        }
      EXPECT_GT(sky, 8);
    }
  }
}

TEST(Light, AZamoOnTheAxisSeesTheDiskShiftedByTheLapses) {
  // Kerr a = 0.9, a ZAMO on the axis at r = 40 (where every ray has L = 0):
  // g_grav = alpha(disk) / alpha(observer), with alpha^2 = Delta Sigma / A:
  // on the axis Delta / (r^2 + a^2), at the equator Delta r^2 / A.  The
  // kinematic part is what is left of hit.g.  Tolerance 1e-6 relative:
  // colours are floats.
  const double a = 0.9, r_o = 40;
  auto delta = [&](double r) { return r * r - 2 * r + a * a; };
  const double alpha_obs = std::sqrt(delta(r_o) / (r_o * r_o + a * a));
  auto alpha_disk = [&](double r) {
    const double A = (r * r + a * a) * (r * r + a * a) - a * a * delta(r);
    return std::sqrt(delta(r) * r * r / A);
  };
  SceneSpec fs;
  fs.spacetime = Kerr(1, a);
  fs.observer = Zamo::Params{{0, r_o, 0, 0}};
  fs.camera.get<PinholeParams>().fov = 40;
  Disk::Params d{2.5, 15, 4, 12};
  d.colors = {plain, plain};
  fs.objects.push_back(d);
  for (const KerrChart chart : {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild}) {
    fs.light = shifted(0, 1, 1, 0);
    int disk = 0;
    for (const RaySample& s : samples(fs, 12, chart))
      if (s.hit.kind == Disk::hit_kind) {
        expect_beamed(s.color, alpha_disk(s.hit.r) / alpha_obs, "gravitational");
        ++disk;
      }
    EXPECT_GT(disk, 30);
    fs.light = shifted(0, 1, 0, 1);
    for (const RaySample& s : samples(fs, 12, chart))
      if (s.hit.kind == Disk::hit_kind) expect_beamed(s.color, s.hit.g * alpha_obs / alpha_disk(s.hit.r), "kinematic");
  }
}

TEST(Light, ARunnersShiftIsAllKinematic) {
  // Flat space: an observer running at 0.6 towards where it looks sees the
  // sky ahead, and a sphere at rest ahead, at g = 2, all of it kinematic.
  SceneSpec fs;
  WorldlineSpec w;
  w.spacetime = Minkowski{};
  w.start = {0, 0, 100, 0};
  w.velocity = {-0.6, 0, 0};
  w.duration = 10;
  w.where = "test";
  FreeFall::Params ride;
  ride.worldline = w;
  fs.observer = ride;
  fs.camera.get<PinholeParams>().fov = 1;
  std::get<CheckerSky::Params>(fs.sky).colors = {plain, plain};
  fs.light = shifted(0, 1, 0, 1);
  expect_beamed(samples(fs, 1)[0].color, 2.0, "kinematic");
  fs.light = shifted(0, 1, 1, 0);
  expect_beamed(samples(fs, 1)[0].color, 1.0, "gravitational");
  Sphere::Params ball;
  ball.radius = 1;
  ball.placement.at = Vec4{0, -50, 100, 0};
  ball.colors = {plain, plain};
  fs.objects.push_back(ball);
  fs.light = shifted(0, 1, 0, 1);
  const RaySample hit = samples(fs, 1)[0];
  ASSERT_EQ(hit.hit.kind, Sphere::hit_kind);
  EXPECT_NEAR(hit.hit.g, 2.0, 1e-9);
  expect_beamed(hit.color, 2.0, "kinematic");
  fs.light = shifted(0, 1, 1, 0);
  expect_beamed(samples(fs, 1)[0].color, 1.0, "gravitational");
}

TEST(Light, ShiftedTexturesAreSeenThroughTheSpectra) {
  // Colour shift and beaming together: the sky seen by the static observer
  // in Schwarzschild is the table's colour at g, in both integrators.
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0);
  fs.observer = StaticObserver::Params{{0, 10, 60 * degree, 0}};
  std::get<CheckerSky::Params>(fs.sky).colors = {plain, plain};
  fs.light = shifted(1, 1, 1, 1);
  const Color expected = SpectralShift()(plain, 1 / std::sqrt(1 - 2.0 / 10));
  for (const KerrChart chart : {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild})
    for (const RaySample& s : samples(fs, 3, chart))
      if (s.hit.kind == HitKind::sky)
        for (int i = 0; i < 3; ++i) EXPECT_NEAR(s.color[i], expected[i], 1e-6 * expected[i]);
}

}  // namespace
}  // namespace lc
