// hit.g, the frequency ratio nu_observed / nu_emitted (docs/light.md),
// against figures known in closed form: the Keplerian disk's energy and
// angular momentum (Bardeen, Press & Teukolsky 1972), the redshift of a
// Kerr disk seen by a static observer (Cunningham 1975), the lapse that
// blueshifts the sky for a static observer, and the special-relativistic
// Doppler factor of a moving sphere and of a moving observer.

#include <gtest/gtest.h>

#include <cmath>

#include "camera/pinhole_params.hpp"
#include "core/constants.hpp"
#include "light/blackbody.hpp"
#include "light/novikov_thorne.hpp"
#include "objects/disk.hpp"
#include "objects/sphere.hpp"
#include "render/renderer.hpp"
#include "render/scene_builder.hpp"
#include "render/scene_visit.hpp"
#include "render/trace.hpp"
#include "render/trace_templates.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"
#include "test_scenes.hpp"

namespace lc {
namespace {

// BL metric of Kerr (M, a) in the equatorial plane: g_tt, g_tphi, g_phiphi.
struct Equatorial {
  double tt, tp, pp;
};
Equatorial equatorial_metric(double M, double a, double r) {
  return {-(1 - 2 * M / r), -2 * M * a / r, r * r + a * a + 2 * M * a * a / r};
}

// Specific energy and angular momentum of the prograde (co-rotating, a >= 0)
// circular orbit at r: Bardeen, Press & Teukolsky (1972), eqs. 2.12-2.13.
double bpt_energy(double M, double a, double r) {
  const double sr = std::sqrt(r), sm = std::sqrt(M);
  return (r * sr - 2 * M * sr + a * sm) / (std::pow(r, 0.75) * std::sqrt(r * sr - 3 * M * sr + 2 * a * sm));
}
double bpt_angular_momentum(double M, double a, double r) {
  const double sr = std::sqrt(r), sm = std::sqrt(M);
  return sm * (r * r - 2 * a * sm * sr + a * a) / (std::pow(r, 0.75) * std::sqrt(r * sr - 3 * M * sr + 2 * a * sm));
}

// u_mu = g_{mu nu} u^nu of an equatorial BL 4-velocity (t, r, theta, phi).
Vec4 lower(double M, double a, double r, const Vec4& u) {
  const Equatorial g = equatorial_metric(M, a, r);
  const double delta = r * r - 2 * M * r + a * a;
  return {g.tt * u[0] + g.tp * u[3], r * r / delta * u[1], 0.0, g.tp * u[0] + g.pp * u[3]};
}

TEST(FrequencyShift, DiskMatterFollowsKeplerOutsideTheIscoAndPlungesInside) {
  // ISCO radii known in closed form: 6M (a = 0), M (a = M, prograde), and
  // BPT's formula at a = 0.9: 2.3209 M.  The matter's conserved u_t, u_phi
  // equal BPT's -E, L at and outside the ISCO and the ISCO's inside it;
  // u.u = -1 everywhere.  Tolerances: rounding of closed forms, 1e-12.
  EXPECT_NEAR(Kerr(1, 0).isco_radius(), 6.0, 1e-12);
  EXPECT_NEAR(Kerr(1, 1).isco_radius(), 1.0, 1e-6);  // cube roots of 0: a cusp, 1e-6 from rounding
  EXPECT_NEAR(Kerr(1, 0.9).isco_radius(), 2.320883041761887, 1e-12);
  EXPECT_NEAR(Kerr(2, 0).isco_radius(), 12.0, 1e-12);
  for (const double a : {0.0, 0.5, 0.9}) {
    const Kerr k(1, a);
    const double ri = k.isco_radius();
    for (const double r : {0.5 * (ri + k.horizon_radius()), 0.9 * ri, ri, 1.5 * ri, 10.0, 40.0}) {
      const Vec4 u = k.disk_velocity_bl(r);
      const Vec4 l = lower(1, a, r, u);
      EXPECT_NEAR(l[0] * u[0] + l[1] * u[1] + l[3] * u[3], -1.0, 1e-12) << "a " << a << " r " << r;
      const double at = std::max(r, ri);
      EXPECT_NEAR(-l[0], bpt_energy(1, a, at), 1e-12) << "a " << a << " r " << r;
      EXPECT_NEAR(l[3], bpt_angular_momentum(1, a, at), 1e-11) << "a " << a << " r " << r;
      if (r < ri) EXPECT_LT(u[1], 0.0) << "plunging inwards";
      else EXPECT_EQ(u[1], 0.0);
    }
  }
  // A hole spinning the other way takes its disk with it: the mirror image.
  const Vec4 up = Kerr(1, 0.7).disk_velocity_bl(8), um = Kerr(1, -0.7).disk_velocity_bl(8);
  EXPECT_DOUBLE_EQ(up[0], um[0]);
  EXPECT_DOUBLE_EQ(up[3], -um[3]);
}

// Every disk pixel of a 16x16 image of a Kerr (M = 1, a) disk from a static
// observer at r = 50, theta; returns how many were checked against
// Cunningham's (1975) closed form
//   g = sqrt(-g_tt - 2 Omega g_tphi - Omega^2 g_phiphi) / (1 - Omega lambda)
//       / sqrt(-g_tt(observer)),
// lambda = L / E of the photon, from the ray's own momentum where it met the
// disk (p_t and p_phi = x p_y - y p_x in Kerr–Schild: the same Killing
// vectors as in Boyer–Lindquist).
int check_disk_against_cunningham(double a, double theta_deg, KerrChart chart) {
  SceneSpec fs;
  fs.spacetime = Kerr(1, a);
  fs.observer = StaticObserver::Params{{0, 50, theta_deg * degree, 0}};
  fs.camera.get<PinholeParams>().fov = 40;
  fs.objects.push_back(Disk::Params{Kerr(1, a).isco_radius(), 18, 4, 12});
  ShotResources res;
  RayOptions o;
  o.kerr_chart = chart;
  const int W = 16;
  const Scene scene = build_scene(fs, W, W, res, o);
  const double r_o = 50, cos_o = std::cos(theta_deg * degree);
  const double gtt_obs = -(1 - 2 * r_o / (r_o * r_o + a * a * cos_o * cos_o));
  int checked = 0;
  for (int j = 0; j < W; ++j)
    for (int i = 0; i < W; ++i) {
      const RaySample s = visit_scene(
          [&](const auto& sc) {
            // A path recorder, even one that keeps nothing, has the Kerr
            // fast path fill hit.end, which this check reads.
            return trace_sample(sc, sc.camera.direction(i + 0.5, j + 0.5), [](const RayState&, double) {});
          },
          scene);
      if (s.hit.kind != Disk::hit_kind) continue;
      const auto& y = s.hit.end;
      const double p_t = y[4], p_phi = y[1] * y[6] - y[2] * y[5];
      const double lambda = -p_phi / p_t;
      const double r = s.hit.r, omega = 1 / (r * std::sqrt(r) + a);
      const Equatorial g = equatorial_metric(1, a, r);
      const double expected = std::sqrt(-g.tt - 2 * omega * g.tp - omega * omega * g.pp) / (1 - omega * lambda) /
                              std::sqrt(-gtt_obs);
      EXPECT_NEAR(s.hit.g, expected, 1e-9 * expected)
          << "a " << a << " theta " << theta_deg << " pixel " << i << "," << j;
      ++checked;
    }
  return checked;
}

TEST(FrequencyShift, DiskSeenByAStaticObserverMatchesCunningham) {
  // Tolerance 1e-9: both sides are evaluated at the event the ray itself
  // found, so only rounding in the charts' conversions separates them.
  for (const KerrChart chart : {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild})
    for (const double a : {0.0, 0.9})
      for (const double theta : {0.0, 75.0}) EXPECT_GT(check_disk_against_cunningham(a, theta, chart), 20);
}

TEST(FrequencyShift, TheSkyIsBlueshiftedByTheStaticObserversLapse) {
  // Light from far away reaches a static observer at r with
  // g = 1 / sqrt(-g_tt): Schwarzschild 1 / sqrt(1 - 2M/r), the dihole U.
  // Tolerance 1e-12: p_t is conserved exactly by both integrators' forms
  // (t is cyclic), so only its start rounds.
  for (const KerrChart chart : {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild}) {
    SceneSpec fs;
    fs.spacetime = Kerr(1, 0);
    fs.observer = StaticObserver::Params{{0, 10, 60 * degree, 0}};
    fs.camera.get<PinholeParams>().fov = 120;
    ShotResources res;
    RayOptions o;
    o.kerr_chart = chart;
    const Scene scene = build_scene(fs, 4, 4, res, o);
    int sky = 0;
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        const RaySample s = trace_image_point(scene, i + 0.5, j + 0.5);
        if (s.hit.kind == HitKind::horizon) {
          EXPECT_EQ(s.hit.g, 0.0);
        }
        if (s.hit.kind != HitKind::sky) continue;
        EXPECT_NEAR(s.hit.g, 1 / std::sqrt(1 - 2.0 / 10), 1e-12);
        ++sky;
      }
    EXPECT_GT(sky, 8);
  }
  SceneSpec di;
  di.spacetime = Dihole(0.4, 0.4, 1.0);
  di.observer = StaticObserver::Params{{0, 6, 2, 1}};
  ShotResources res;
  const Scene scene = build_scene(di, 1, 1, res);
  const RaySample s =
      trace_image_point(scene, 0.5, 0.5);
  ASSERT_EQ(s.hit.kind, HitKind::sky);
  EXPECT_NEAR(s.hit.g, Dihole(0.4, 0.4, 1.0).potential({0, 6, 2, 1}), 1e-12);
}

// The sample of the ray through the centre of a 2x2 image of fs.
RaySample centre_sample(const SceneSpec& fs) {
  ShotResources res;
  const Scene scene = build_scene(fs, 2, 2, res);
  return trace_image_point(scene, 1.0, 1.0);
}

TEST(FrequencyShift, SpheresAndObserversInFlatSpaceGiveTheDopplerFactor) {
  // A static observer at y = 100 looks along -y at the origin.
  SceneSpec fs;
  fs.observer = StaticObserver::Params{{0, 0, 100, 0}};
  fs.camera.get<PinholeParams>().fov = 10;

  // A sphere at rest: no shift at all (exact: p_t = 1 and u = e_t).
  SceneSpec rest = fs;
  Sphere::Params sp;
  sp.radius = 1.0;
  sp.placement.at = Vec4{0, 0, 0, 0};
  rest.objects.push_back(sp);
  const RaySample at_rest = centre_sample(rest);
  ASSERT_EQ(at_rest.hit.kind, Sphere::hit_kind);
  EXPECT_EQ(at_rest.hit.g, 1.0);

  // Moving at v = 0.6 straight at the observer: sqrt((1 + v) / (1 - v)) = 2
  // (tolerance 1e-9: the worldline's 4-velocity is integrated, constant in
  // flat space to rounding); moving away: 1/2.
  for (const double v : {0.6, -0.6}) {
    SceneSpec moving = fs;
    moving.objects.push_back(test::falling_sphere(Minkowski{}, {-300, 0, -180 * v / 0.6, 0}, {0, v, 0}, 400, 1.0));
    const RaySample s = centre_sample(moving);
    ASSERT_EQ(s.hit.kind, Sphere::hit_kind) << "v " << v;
    EXPECT_NEAR(s.hit.g, std::sqrt((1 + v) / (1 - v)), 1e-9) << "v " << v;
  }

  // An observer moving at 0.6 towards where it looks sees the sky ahead
  // blueshifted by the same factor 2 (its frame's time leg is boosted).  A
  // free-falling camera looks along -e_1 of its frame, here the boosted
  // Cartesian frame's -x; sideways (along y) it sees the sky redshifted by
  // 1 / gamma = 0.8 at the image centre, where the light arrives
  // perpendicular to the motion in its own frame.
  SceneSpec runner;
  WorldlineSpec w;
  w.spacetime = Minkowski{};
  w.start = {0, 0, 100, 0};
  w.duration = 10;
  w.where = "test";
  for (const auto& [velocity, expected] : {std::pair{Vec3{-0.6, 0, 0}, 2.0}, std::pair{Vec3{0, 0.6, 0}, 0.8}}) {
    w.velocity = velocity;
    FreeFall::Params ride;
    ride.worldline = w;
    ride.proper_time = 0;
    runner.observer = ride;
    const RaySample s = centre_sample(runner);
    ASSERT_EQ(s.hit.kind, HitKind::sky);
    EXPECT_NEAR(s.hit.g, expected, 1e-12);
  }
}

}  // namespace
}  // namespace lc

namespace lc {
namespace {

// A 24x16 image of a glowing disk (Kerr a, static observer at r = 30,
// 75 deg) on a black sky, seen shifted, as colours.
std::vector<Color> glowing_disk(double a, KerrChart chart) {
  SceneSpec fs;
  fs.spacetime = Kerr(1, a);
  fs.observer = StaticObserver::Params{{0, 30, 75 * degree, 0}};
  fs.camera.get<PinholeParams>().fov = 50;
  Disk::Params d{2, 20, 4, 12};
  d.temperature = 8000;
  fs.objects.push_back(d);
  fs.light.model = LightModel::shifted;
  std::get<CheckerSky::Params>(fs.sky).colors = {{0, 0, 0}, {0, 0, 0}};  // a black sky: no checker to mirror
  ShotResources res;
  RayOptions o;
  o.kerr_chart = chart;
  const Scene scene = build_scene(fs, 24, 16, res, o);
  std::vector<Color> out;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 24; ++i)
      out.push_back(trace_image_point(scene, i + 0.5, j + 0.5).color);
  return out;
}

double luminance(const Color& c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; }

TEST(GlowingDisk, TheApproachingSideIsBrighterAndFlipsWithTheSpin) {
  // The image for -a is the mirror image of the one for a (the reflection
  // phi -> -phi maps the scene for a onto the one for -a and the camera's
  // right onto its left); the colours depend on r and g alone.  Tolerance
  // 1e-4 relative: mirrored rays are integrated with mirrored but not
  // bit-identical arithmetic.  Beaming makes the side whose matter comes
  // towards the camera several times brighter.
  for (const KerrChart chart : {KerrChart::boyer_lindquist_mino, KerrChart::kerr_schild}) {
    const std::vector<Color> plus = glowing_disk(0.9, chart), minus = glowing_disk(-0.9, chart);
    double left = 0, right = 0;
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 24; ++i) {
        const Color &p = plus[j * 24 + i], &m = minus[j * 24 + (23 - i)];
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], m[c], 1e-4 * std::max(1.0f, p[c])) << i << "," << j;
        (i < 12 ? left : right) += luminance(p);
      }
    EXPECT_GT(std::max(left, right), 2 * std::min(left, right)) << "left " << left << " right " << right;
  }
}

TEST(GlowingDisk, InPhysicalUnitsItsLightIsInCandelasPerSquareMetre) {
  // A hole standing for 4.3e6 Suns accreting 1e-8 of a Sun a year (the
  // hottest ring ~9600 K), seen in the paper's look (unshifted): each disk
  // pixel's luminance is 683 lm/W times the y-bar-weighted Planck radiance
  // at its ring's temperature.  Tolerance 1e-3: the colour table's
  // interpolation (1e-4) and the sRGB matrices' rounding.
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0.9);
  fs.observer = StaticObserver::Params{{0, 30, 20 * degree, 0}};
  fs.camera.get<PinholeParams>().fov = 50;
  Disk::Params d{2.4, 12, 4, 12};
  d.solar_masses = 4.3e6;
  d.accretion_rate = 1e-8;
  fs.objects.push_back(d);
  ShotResources res;
  const Scene scene = build_scene(fs, 12, 12, res);
  const NovikovThorneFlux flux(1, 0.9);
  int disk = 0;
  for (int j = 0; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      const RaySample s = trace_image_point(scene, i + 0.5, j + 0.5);
      if (s.hit.kind != Disk::hit_kind) continue;
      const double expected = 683 * blackbody_xyz(flux.temperature(s.hit.r, 4.3e6, 1e-8)).Y;
      EXPECT_NEAR(luminance(s.color), expected, 1e-3 * expected) << i << "," << j;
      ++disk;
    }
  EXPECT_GT(disk, 20);
}

TEST(GlowingDisk, PhysicalUnitsBeyondWhatCanBeShownAreRefused) {
  // 1e12 Suns accreting 1e-30 of a Sun a year: the hottest ring would be
  // far below 1 K.  A clear error naming both fields, no scene.
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0.5);
  fs.observer = StaticObserver::Params{{0, 30, 80 * degree, 0}};
  Disk::Params d{3, 12, 4, 12};
  d.solar_masses = 1e12;
  d.accretion_rate = 1e-30;
  fs.objects.push_back(d);
  ShotResources res;
  try {
    build_scene(fs, 4, 4, res);
    FAIL() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("solar_masses = 1e+12, accretion_rate = 1e-30 makes the hottest ring"),
              std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("outside the 1 K to 1e9 K lightcone shows"), std::string::npos) << e.what();
  }
}

TEST(GlowingDisk, NeedsAKerrHole) {
  // Around a dihole, an extremal Kerr hole (its disk's inner edge would be
  // on the horizon) and an extremal charged one: a clear error, no scene.
  SceneSpec di;
  di.spacetime = Dihole(0.4, 0.4, 1.0);
  di.observer = StaticObserver::Params{{0, 0, 30, 0}};
  SceneSpec extremal;
  extremal.spacetime = Kerr(1, 1);
  extremal.observer = StaticObserver::Params{{0, 30, 80 * degree, 0}};
  SceneSpec charged = extremal;  // a^2 + Q^2 = M^2
  charged.spacetime = Kerr(1, 0.6, 0.8);
  for (SceneSpec fs : {di, extremal, charged}) {
    Disk::Params d{2, 20, 4, 12};
    d.temperature = 8000;
    fs.objects.push_back(d);
    ShotResources res;
    try {
      build_scene(fs, 4, 4, res);
      ADD_FAILURE() << "a glowing disk was built around " << describe(fs.spacetime);
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("needs a Kerr or Kerr–Newman hole with mass > 0 and spin^2 + charge^2 < mass^2"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace lc
