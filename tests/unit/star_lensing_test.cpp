// Point stars through the renderer (stars/star_pass.hpp on the directions
// the rays of a frame escaped in), against the point-lens formulas in the
// weak field: a Schwarzschild hole (M = 1) seen by a static observer at
// r = D (Einstein angle theta_E = sqrt(4M / D)), a star at infinity at beta = u theta_E behind it.  The
// two images lie where the lens equation puts them, theta = (beta +-
// sqrt(beta^2 + 4 theta_E^2)) / 2, with magnifications mu+- = (u^2 + 2) /
// (2u sqrt(u^2 + 4)) +- 1/2.  Tolerance 1%: the corrections beyond the
// weak-field formulas are O(M / b) ~ 0.5% here (D = 1e5 M: b ~ 400-600 M),
// the 200 x 200 pixels' (mu interpolated at the star) a few 0.1%.  At the
// production integrator tolerance.

#include <algorithm>
#include <gtest/gtest.h>

#include <cmath>

#include "camera/fisheye.hpp"
#include "camera/pinhole_params.hpp"
#include "core/constants.hpp"
#include "render/scene_builder.hpp"
#include "render/trace.hpp"
#include "spacetime/kerr.hpp"
#include "stars/sky_quad.hpp"
#include "stars/star_pass.hpp"

namespace lc {
namespace {

TEST(StarLensing, ASchwarzschildHolesTwoImagesFollowThePointLens) {
  const int N = 200;
  const double D = 1e5, theta_e = std::sqrt(4 / D);
  SceneSpec fs;
  fs.spacetime = Kerr(1, 0);
  fs.observer = StaticObserver::Params{{0, D, 90 * degree, 0}};
  fs.camera.get<PinholeParams>().fov = 4 * std::sqrt(1e4 / D);
  ShotResources res;
  RayOptions rays;
  const Scene scene = build_scene(fs, N, N, res, rays);
  const auto& sc = scene_get<Kerr>(scene);
  std::vector<Vec3> dirs;
  for (int j = 0; j < N; ++j)
    for (int i = 0; i < N; ++i) dirs.push_back(sc.camera.direction(i + 0.5, j + 0.5));
  std::vector<RaySample> samples(dirs.size());
  trace_batch(sc, std::span<const Vec3>(dirs), std::span<RaySample>(samples));
  std::vector<SkyPoint> sky;
  for (const RaySample& s : samples) sky.push_back(s.sky);
  // The camera's pixels' solid angles, from its local directions at their
  // corners (its frame is orthonormal).
  auto omega = [&](int i, int j) {
    return SkyQuad{{unit3(sc.camera.direction(i, j)), unit3(sc.camera.direction(i + 1, j)),
                    unit3(sc.camera.direction(i + 1, j + 1)), unit3(sc.camera.direction(i, j + 1))}}
        .area();
  };
  for (const double u : {0.5, 1.0}) {
    const double beta = u * theta_e;
    const StarField field({{unit3({-std::cos(beta), 0, std::sin(beta)}), {1, 1, 1}}}, nullptr, nullptr);
    std::vector<float> image(3 * dirs.size(), 0.0f);
    const auto camera = [&](double x, double y) { return unit3(sc.camera.direction(x, y)); };
    EXPECT_EQ(add_point_stars(sky, N, N, field, camera, StarPassOptions{}, image), 2) << "u " << u;
    // Each image's light and its centroid's angle from the axis (the
    // image's centre: the camera looks at the hole), signed along the
    // star's side.
    double flux[2] = {0, 0}, angle[2] = {0, 0};
    const Vec3 axis = unit3(sc.camera.direction(0.5 * N, 0.5 * N));
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) {
        const float r = image[3 * static_cast<std::size_t>(j * N + i)];
        if (r <= 0) continue;
        const Vec3 n = unit3(sc.camera.direction(i + 0.5, j + 0.5));
        const double a = std::acos(std::clamp(n[0] * axis[0] + n[1] * axis[1] + n[2] * axis[2], -1.0, 1.0));
        const int side = j < N / 2 ? 0 : 1;
        flux[side] += r * omega(i, j);
        angle[side] += r * omega(i, j) * a;
      }
    const double root = std::sqrt(u * u + 4);
    const double mu_plus = (u * u + 2) / (2 * u * root) + 0.5, mu_minus = mu_plus - 1;
    const double theta_plus = 0.5 * (beta + std::sqrt(beta * beta + 4 * theta_e * theta_e));
    const double theta_minus = 0.5 * (std::sqrt(beta * beta + 4 * theta_e * theta_e) - beta);
    // Which half holds the primary image depends on the camera's up:
    // the brighter one is the primary.
    const int primary = flux[0] > flux[1] ? 0 : 1;
    EXPECT_NEAR(flux[primary], mu_plus, 0.01 * mu_plus) << "u " << u;
    EXPECT_NEAR(flux[1 - primary], mu_minus, 0.01 * mu_minus) << "u " << u;
    EXPECT_NEAR(angle[primary] / flux[primary], theta_plus, 0.01 * theta_plus) << "u " << u;
    EXPECT_NEAR(angle[1 - primary] / flux[1 - primary], theta_minus, 0.01 * theta_minus) << "u " << u;
  }
}

// The same point lens through the fisheye (a dome master), its images and
// magnifications where the projection puts them.  The lens is the
// Schwarzschild point lens's map on the sky, beta = theta - theta_E^2 /
// theta (angles from the lens's axis, each ray's sky direction turned
// towards the axis in its own plane; a shadow within 0.3 theta_E),
// applied to the camera's own directions: so its images are exactly at
// theta+- = (beta +- sqrt(beta^2 + 4 theta_E^2)) / 2 and magnified by
// mu = |sin theta / sin beta  dtheta / dbeta| on the sphere (the small-angle
// formula's mu differs from it by ~theta^2 / 6, 0.1% here).  theta_E =
// 5 degrees, the lens at the disc's centre and 50 degrees out towards its
// edge (where the projection stretches pixels sideways by 12%), a
// 180-degree disc at 1000 x 1000: the ring ~28 pixels across.  Tolerance
// 1%, the pinhole's.
TEST(StarLensing, ThroughTheFisheyeAPointLensesImagesAreThePinholes) {
  const int N = 1000;
  const double theta_e = 5 * degree;
  FisheyeParams p;
  p.full_angle = 180;
  const FisheyeCamera cam(p, N, N);
  for (const double off : {0.0, 50.0}) {
    // The lens's axis, `off` degrees from the camera's towards its right.
    Vec3 axis;
    for (int k = 0; k < 3; ++k)
      axis[k] = std::cos(off * degree) * cam.axes().forward[k] + std::sin(off * degree) * cam.axes().right[k];
    // A unit vector at angle a from the axis, in the plane of the axis and
    // unit vector e (perpendicular to it).
    auto at_angle = [&](double a, const Vec3& e) {
      return Vec3{std::cos(a) * axis[0] + std::sin(a) * e[0], std::cos(a) * axis[1] + std::sin(a) * e[1],
                  std::cos(a) * axis[2] + std::sin(a) * e[2]};
    };
    std::vector<SkyPoint> sky(static_cast<std::size_t>(N) * N);
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i) {
        SkyPoint& sp = sky[static_cast<std::size_t>(j) * N + i];
        const Vec3 d = cam.direction(i + 0.5, j + 0.5);
        const double c = std::clamp(dot3(d, axis), -1.0, 1.0), t = std::acos(c);
        if (!cam.ray({i + 0.5, j + 0.5, 0.0}) || t < 0.3 * theta_e) continue;  // outside the disc; the shadow
        const Vec3 e = unit3({d[0] - c * axis[0], d[1] - c * axis[1], d[2] - c * axis[2]});
        const Vec3 src = at_angle(t - theta_e * theta_e / t, e);
        sp.theta = std::acos(std::clamp(src[2], -1.0, 1.0));
        sp.phi = std::atan2(src[1], src[0]);
        if (sp.phi < 0) sp.phi += two_pi;
      }
    const auto camera = [&](double x, double y) { return unit3(cam.direction(x, y)); };
    auto omega = [&](int i, int j) {
      return SkyQuad{{camera(i, j), camera(i + 1, j), camera(i + 1, j + 1), camera(i, j + 1)}}.area();
    };
    // The star: beta = u theta_E from the axis, towards the camera's up.
    const Vec3 up = cam.axes().up;
    const Vec3 e_star = unit3({up[0] - dot3(up, axis) * axis[0], up[1] - dot3(up, axis) * axis[1],
                               up[2] - dot3(up, axis) * axis[2]});
    for (const double u : {0.5, 1.0}) {
      const double beta = u * theta_e;
      const StarField field({{at_angle(beta, e_star), {1, 1, 1}}}, nullptr, nullptr);
      std::vector<float> image(3 * sky.size(), 0.0f);
      EXPECT_EQ(add_point_stars(sky, N, N, field, camera, StarPassOptions{}, image), 2) << "off " << off << " u " << u;
      // Each image's light and its light-weighted angle from the axis,
      // signed: on the star's side of the axis or across it.
      double flux[2] = {0, 0}, angle[2] = {0, 0};
      for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
          const float r = image[3 * (static_cast<std::size_t>(j) * N + i)];
          if (r <= 0) continue;
          const Vec3 d = camera(i + 0.5, j + 0.5);
          const int side = dot3(d, e_star) > 0 ? 0 : 1;
          flux[side] += r * omega(i, j);
          angle[side] += r * omega(i, j) * std::acos(std::clamp(dot3(d, axis), -1.0, 1.0));
        }
      const double root = std::sqrt(beta * beta + 4 * theta_e * theta_e);
      const double images[2] = {0.5 * (beta + root), 0.5 * (root - beta)};  // the second across the axis
      for (int k = 0; k < 2; ++k) {
        const double t = images[k];
        const double mu = std::abs(std::sin(t) / std::sin(t - theta_e * theta_e / t) / (1 + theta_e * theta_e / (t * t)));
        EXPECT_NEAR(flux[k], mu, 0.01 * mu) << "off " << off << " u " << u << " image " << k;
        EXPECT_NEAR(angle[k] / flux[k], t, 0.01 * t) << "off " << off << " u " << u << " image " << k;
      }
    }
  }
}

}  // namespace
}  // namespace lc
