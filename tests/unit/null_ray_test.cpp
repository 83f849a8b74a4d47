// The production null-ray integrator against figures known independently of
// this code: the Schwarzschild critical impact parameter sqrt(27) M, the
// constants of motion of Kerr (E, L_z, Carter's Q), straight lines in flat
// space, and agreement with the GSL reference integrator.

#include <gtest/gtest.h>

#include <cmath>

#include "core/constants.hpp"
#include "eye/ray_direction.hpp"
#include "geodesic/crossing.hpp"
#include "geodesic/geodesic_solver.hpp"
#include "geodesic/null_ray.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"

namespace lc {
namespace {

// A ray leaving a static observer at (r0, equator, phi = 0) whose impact
// parameter is b: sin(alpha) = (b / r0) sqrt(1 - 2M/r0) from -e_r towards e_phi.
RayResult schwarzschild_ray(double b, double r0 = 200.0) {
  const Kerr k(1.0, 0.0);
  const Vec4 s = {0, r0, 0.5 * pi, 0};
  const Tetrad t = static_polar_tetrad(k, s);
  const double sa = b / r0 * std::sqrt(1 - 2 / r0);
  const Vec4 x = k.trace_from_scene(s);
  const Vec4 p = backward_ray_momentum(k.metric(x), t, {-std::sqrt(1 - sa * sa), 0.0, sa});
  return trace_null_ray(k, x, p, RayOptions{});
}

TEST(NullRay, SchwarzschildCriticalImpactParameter) {
  // Rays within 0.1% of b_c = sqrt(27) M wind a few times around the photon
  // sphere before deciding; the integrator must decide correctly.
  const double bc = std::sqrt(27.0);
  for (double eps : {1e-2, 1e-3, 1e-4}) {
    EXPECT_EQ(schwarzschild_ray(bc * (1 - eps)).reason, StopReason::horizon) << eps;
    EXPECT_EQ(schwarzschild_ray(bc * (1 + eps)).reason, StopReason::escaped) << eps;
  }
}

struct Constants {
  double E, Lz, Q;
};

// E = -p_t, L_z = x p_y - y p_x (∂_phi in Kerr–Schild), and Carter's
// Q = p_theta^2 + cos^2(theta) (-a^2 E^2 + L_z^2 / sin^2(theta)) for null rays,
// with p_theta = p_mu ∂x^mu/∂theta from the Boyer–Lindquist map.
Constants constants(const Kerr& k, const RayState& y) {
  const Vec4 x = {y[0], y[1], y[2], y[3]};
  const Vec4 s = k.scene_from_trace(x);
  const Mat4 J = k.trace_jacobian(s);
  double pth = 0.0;
  for (int m = 0; m < 4; ++m) pth += y[4 + m] * J[m][2];
  const double E = -y[4], Lz = y[1] * y[6] - y[2] * y[5];
  const double c = std::cos(s[2]), sn = std::sin(s[2]);
  const double a = k.spin();
  return {E, Lz, pth * pth + c * c * (-a * a * E * E + Lz * Lz / (sn * sn))};
}

TEST(NullRay, KerrConstantsOfMotionAreConserved) {
  // The bench camera: a = 0.9, static observer at r = 30, theta = 80 deg.
  // Every accepted step of a grid of rays across the 40 deg field of view is
  // checked.  Relative drift is measured against the natural scales E, E M
  // and E^2 M^2 where a constant is near zero.
  const Kerr k(1.0, 0.9);
  const Vec4 s = {0, 30, 80 * degree, 0};
  const Tetrad t = static_polar_tetrad(k, s);
  const Vec4 x = k.trace_from_scene(s);
  const Mat4 g = k.metric(x);
  double worst_E = 0, worst_L = 0, worst_Q = 0;
  int captured = 0, escaped = 0;
  const double tan_half = std::tan(20 * degree);
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      const double u = (2 * (i + 0.5) / 9 - 1) * tan_half, v = (1 - 2 * (j + 0.5) / 9) * tan_half;
      const Vec4 p = backward_ray_momentum(g, t, {-1.0, -v, u});
      const RayState y0 = {x[0], x[1], x[2], x[3], p[0], p[1], p[2], p[3]};
      const Constants c0 = constants(k, y0);
      auto check = [&](const RayStep& step, RayResult&) {
        const RayState y = step.at(step.t0 + step.h);
        const Constants c = constants(k, y);
        worst_E = std::max(worst_E, std::abs(c.E - c0.E) / c0.E);
        worst_L = std::max(worst_L, std::abs(c.Lz - c0.Lz) / std::max(std::abs(c0.Lz), c0.E));
        worst_Q = std::max(worst_Q, std::abs(c.Q - c0.Q) / std::max(std::abs(c0.Q), c0.E * c0.E));
        return false;
      };
      RayOptions o;
      o.kerr_chart = KerrChart::kerr_schild;
      o.control.rtol = o.control.atol = conservation_ray_tolerance;
      const NullRayResult r = trace_null_ray(k, x, p, o, check);
      (r.reason == StopReason::horizon ? captured : escaped)++;
      EXPECT_LT(std::abs(r.hamiltonian), 1e-8 * c0.E * c0.E);  // the null condition holds
      EXPECT_TRUE(r.reason == StopReason::horizon || r.reason == StopReason::escaped);
    }
  EXPECT_GT(captured, 0);
  EXPECT_GT(escaped, 0);
  EXPECT_LT(worst_E, 1e-14);  // p_t is exactly constant in the Hamiltonian form
  EXPECT_LT(worst_L, 1e-8);
  EXPECT_LT(worst_Q, 1e-8);
  RecordProperty("worst_Lz_drift", std::to_string(worst_L));
  RecordProperty("worst_Q_drift", std::to_string(worst_Q));
}

TEST(NullRay, MasslessDiholeRaysAreStraight) {
  const Dihole d(0.0, 0.0, 1.0);
  const Vec4 x = {0, 0, 50, 0};
  const Vec4 p = backward_ray_momentum(d.metric(x), static_cartesian_tetrad(d, x), {0.1, -1.0, 0.2});
  const NullRayResult r = trace_null_ray(d, x, p, RayOptions{});
  ASSERT_EQ(r.reason, StopReason::escaped);
  const double s = (r.y[2] - x[2]) / -1.0;  // distance along -y per unit direction component
  EXPECT_NEAR(r.y[1], x[1] + 0.1 * s, 1e-9 * s);
  EXPECT_NEAR(r.y[3], x[3] + 0.2 * s, 1e-9 * s);
}

TEST(NullRay, FlatSpaceRaysAreStraight) {
  const Kerr flat(0.0, 0.0);
  const Vec4 s = {0, 20, 1.0, 0.4};
  const Vec4 x = flat.trace_from_scene(s);
  const Tetrad t = static_polar_tetrad(flat, s);
  const Vec3 n = {-0.8, 0.3, 0.52};
  const Vec4 p = backward_ray_momentum(flat.metric(x), t, n);
  const NullRayResult r = trace_null_ray(flat, x, p, RayOptions{});
  ASSERT_EQ(r.reason, StopReason::escaped);
  // Spatial direction of the backward ray: dx^i/dlambda = p_i (flat).
  const Vec3 d = {p[1], p[2], p[3]};
  const Vec3 dx = {r.y[1] - x[1], r.y[2] - x[2], r.y[3] - x[3]};
  const double along = (dx[0] * d[0] + dx[1] * d[1] + dx[2] * d[2]) / norm3(d);
  const Vec3 perp = {dx[0] - along * d[0] / norm3(d), dx[1] - along * d[1] / norm3(d), dx[2] - along * d[2] / norm3(d)};
  EXPECT_LT(norm3(perp), 1e-9 * along);
  // Backwards in time by exactly the distance travelled.
  EXPECT_NEAR(x[0] - r.y[0], along, 1e-9 * along);
}

// Position at affine parameter L from the production integrator's dense output.
Vec4 dp5_position_at(const Kerr& k, const Vec4& x, const Vec4& p, double L, double tol) {
  Vec4 out{};
  RayOptions o;
  o.control.rtol = o.control.atol = tol;
  trace_null_ray(k, x, p, o, [&](const RayStep& s, RayResult&) {
    if (s.t0 <= L && L <= s.t0 + s.h) {
      const auto y = s.at(L);
      out = {y[0], y[1], y[2], y[3]};
      return true;
    }
    return false;
  });
  return out;
}

TEST(NullRay, AgreesWithGslReference) {
  const Kerr k(1.0, 0.9);
  const Vec4 s = {0, 30, 80 * degree, 0};
  const Vec4 x = k.trace_from_scene(s);
  const Tetrad t = static_polar_tetrad(k, s);
  const Vec4 p = backward_ray_momentum(k.metric(x), t, {-1.0, 0.12, 0.2});
  // The reference solves the same Hamiltonian system with GSL's rk8pd at 1e-13.
  GeodesicProblem pb;
  pb.spacetime = k;
  pb.x0 = x;
  pb.u0 = mat_vec(k.inverse_metric(x), p);  // past-directed tangent...
  pb.u0 = -1.0 * pb.u0;                      // ...as the future-directed one, integrated to the past
  pb.direction = TimeDirection::past;
  pb.stop_value = 45.0;
  pb.samples = 2;
  pb.tolerance = 1e-13;
  const GeodesicPath ref = solve_geodesic(pb);
  ASSERT_EQ(ref.reason, StopReason::reached);
  const Vec4 xr = ref.samples.back().x;
  // At 1e-10 the two agree to 1e-7 M after 45 M of path; at the production
  // tolerance (chosen by image error) to ~1e-5 M.
  const Vec4 xd = dp5_position_at(k, x, p, 45.0, conservation_ray_tolerance);
  for (int m = 1; m < 4; ++m) EXPECT_NEAR(xd[m], xr[m], 1e-7) << m;
  const Vec4 xp = dp5_position_at(k, x, p, 45.0, default_ray_tolerance);
  for (int m = 1; m < 4; ++m) EXPECT_NEAR(xp[m], xr[m], 1e-5) << m;
}

TEST(NullRay, EquatorialCrossingIsLocatedFromDenseOutput) {
  // A ray from above the plane that crosses it: the located crossing must lie
  // on z = 0 according to the GSL reference at that affine parameter, to far
  // better than the step length.
  const Kerr k(1.0, 0.9);
  const Vec4 s = {0, 30, 70 * degree, 0};
  const Vec4 x = k.trace_from_scene(s);
  const Tetrad t = static_polar_tetrad(k, s);
  const Vec4 p = backward_ray_momentum(k.metric(x), t, {-1.0, 0.3, 0.1});
  double lam = -1, step_len = 0;
  trace_null_ray(k, x, p, RayOptions{}, [&](const RayStep& st, RayResult&) {
    const double z0 = st.start()[3], z1 = st.component(3, st.t0 + st.h);
    if ((z0 > 0) != (z1 > 0)) {
      lam = locate_crossing(st, [](const RayState& y) { return y[3]; }, z0, z1);
      step_len = st.h;
      return true;
    }
    return false;
  });
  ASSERT_GT(lam, 0);
  EXPECT_GT(step_len, 0.05);  // the crossing did not need tiny steps
  GeodesicProblem pb;
  pb.spacetime = k;
  pb.x0 = x;
  pb.u0 = -1.0 * mat_vec(k.inverse_metric(x), p);
  pb.direction = TimeDirection::past;
  pb.stop_value = lam;
  pb.tolerance = 1e-13;
  const GeodesicPath ref = solve_geodesic(pb);
  EXPECT_NEAR(ref.samples.back().x[3], 0.0, 1e-7);
}

}  // namespace
}  // namespace lc
