#include "spacetime/kottler.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"

namespace lc {

Kottler::Kottler(double mass, double lambda, double sense)
    : M_(mass), lambda_(lambda), lambda3_(lambda / 3.0), sense_(sense) {
  if (!std::isfinite(mass) || !std::isfinite(lambda))
    throw std::invalid_argument("kottler: mass and lambda must be finite numbers");
  if (mass < 0.0) throw std::invalid_argument(fmt::format("kottler: mass must be >= 0, got {}", mass));
  if (!(lambda > 0.0))
    throw std::invalid_argument(fmt::format(
        "kottler: lambda must be > 0, got {} (lambda = 0 is Schwarzschild: lc.kerr{{mass = {}}})", lambda, mass));
  if (!(9.0 * lambda * mass * mass < 1.0))
    throw std::invalid_argument(fmt::format(
        "kottler: 9 lambda M^2 must be < 1, got {:.6g} (lambda = {}, M = {}): with a cosmological constant this large "
        "there is no static region between the horizons; lambda < {:.6g} for this mass",
        9.0 * lambda * mass * mass, lambda, mass, 1.0 / (9.0 * mass * mass)));
  // The roots of r^3 - (3/Λ) r + 6M/Λ = -(3/Λ) r F(r), trigonometrically
  // (three real roots while 9ΛM^2 < 1), then two Newton steps each: the
  // hole's is a small difference of cosines when Λ M^2 is small.
  const double k = 2.0 / std::sqrt(lambda), phi = std::acos(-3.0 * mass * std::sqrt(lambda));
  auto cubic = [&](double r) { return r * r * r - 3.0 / lambda * r + 6.0 * mass / lambda; };
  auto polish = [&](double r) {
    for (int i = 0; i < 2; ++i) {
      const double d = 3.0 * r * r - 3.0 / lambda;
      if (d != 0.0) r -= cubic(r) / d;
    }
    return r;
  };
  r_c_ = polish(k * std::cos(phi / 3.0));
  r_b_ = mass > 0.0 ? polish(k * std::cos(phi / 3.0 - 2.0 * pi / 3.0)) : 0.0;
  r_n_ = -(r_b_ + r_c_);
  const double roots[3] = {r_b_, r_c_, r_n_};
  for (int i = 0; i < 3; ++i) {
    double den = 1.0;
    for (int j = 0; j < 3; ++j)
      if (j != i) den *= roots[i] - roots[j];
    residue_[i] = -3.0 / lambda * roots[i] / den;
  }
  if (M_ > 0.0) r_capture_ = std::max(r_b_ + kerr_capture_fraction * (3.0 * M_ - r_b_), r_b_ * (1.0 + 1e-3));
  // F = kottler_stop_lapse2 between the photon sphere and r_c, where F
  // falls monotonically: bisection.
  double lo = std::max(3.0 * M_, 0.0), hi = r_c_;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * r_c_; ++i) {
    const double mid = 0.5 * (lo + hi);
    (lapse2(mid) > kottler_stop_lapse2 ? lo : hi) = mid;
  }
  r_stop_ = lo;
  r_stop2_ = r_stop_ * r_stop_;
  sky_lapse_ = std::sqrt(1.0 - std::cbrt(9.0 * lambda * mass * mass));
}

std::vector<SpacetimeExample<Kottler>> Kottler::examples() {
  std::vector<SpacetimeExample<Kottler>> out;
  for (const double sense : {1.0, -1.0}) {
    out.push_back({Kottler(1.0, 0.01, sense), 2.5, 15.0});   // r_b 2.03, r_c 16.2
    out.push_back({Kottler(1.0, 1e-4, sense), 2.1, 150.0});  // r_c 172
    out.push_back({Kottler(0.0, 0.01, sense), 0.5, 15.0});   // de Sitter, r_c 17.3
  }
  return out;
}

double Kottler::time_function(double r) const {
  const double roots[3] = {r_b_, r_c_, r_n_};
  double T = -r;
  for (int i = 0; i < 3; ++i)
    if (residue_[i] != 0.0) T += residue_[i] * std::log(std::abs(r - roots[i]));
  return T;
}

Vec3 Kottler::escape_direction(const Vec4& x, const Vec3& d) const {
  const Vec3 p = {x[1], x[2], x[3]};
  const double pd = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
  const double pp = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
  const double s = -pd + std::sqrt(std::max(pd * pd - (pp - r_c_ * r_c_), 0.0));
  Vec3 q = {p[0] + s * d[0], p[1] + s * d[1], p[2] + s * d[2]};
  const double n = norm3(q);
  for (auto& c : q) c /= n;
  return q;
}

Mat4 Kottler::metric(const Vec4& x) const {
  const double r = radius(x), h = 2.0 * M_ / r + lambda3_ * r * r;
  const Vec4 l = {sense_, x[1] / r, x[2] / r, x[3] / r};
  Mat4 g = minkowski_metric;
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) g[m][n] += h * l[m] * l[n];
  return g;
}

Mat4 Kottler::inverse_metric(const Vec4& x) const {
  const double r = radius(x), h = 2.0 * M_ / r + lambda3_ * r * r;
  const Vec4 lu = {-sense_, x[1] / r, x[2] / r, x[3] / r};
  Mat4 g = minkowski_metric;
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) g[m][n] -= h * lu[m] * lu[n];
  return g;
}

Mat4Derivs Kottler::metric_derivatives(const Vec4& x) const {
  const double r = radius(x), h = 2.0 * M_ / r + lambda3_ * r * r;
  const double dh = -2.0 * M_ / (r * r) + 2.0 * lambda3_ * r;
  const Vec4 l = {sense_, x[1] / r, x[2] / r, x[3] / r};
  Mat4Derivs d{};
  for (int j = 1; j <= 3; ++j) {
    // ∂_j l_t = 0, ∂_j l_i = (δ_ij - n_i n_j) / r.
    Vec4 dl{};
    for (int i = 1; i <= 3; ++i) dl[i] = ((i == j ? 1.0 : 0.0) - l[i] * l[j]) / r;
    for (int m = 0; m < 4; ++m)
      for (int n = 0; n < 4; ++n) d[j][m][n] = dh * l[j] * l[m] * l[n] + h * (dl[m] * l[n] + l[m] * dl[n]);
  }
  return d;
}

Mat4 Kottler::static_metric(const Vec4& s) const {
  const double r = s[1], F = lapse2(r), sn = std::sin(s[2]);
  Mat4 g{};
  g[0][0] = -F;
  g[1][1] = 1.0 / F;
  g[2][2] = r * r;
  g[3][3] = r * r * sn * sn;
  return g;
}

Vec4 Kottler::trace_from_scene(const Vec4& s) const {
  const double r = s[1], sn = std::sin(s[2]);
  return {s[0] + sense_ * time_function(r), r * sn * std::cos(s[3]), r * sn * std::sin(s[3]), r * std::cos(s[2])};
}

Vec4 Kottler::scene_from_trace(const Vec4& x) const {
  const double r = radius(x);
  // atan2, not acos(z/r): exact to rounding near the axis too.
  const double th = r > 0.0 ? std::atan2(std::hypot(x[1], x[2]), x[3]) : 0.5 * pi;
  double phi = std::atan2(x[2], x[1]);
  if (phi < 0.0) phi += two_pi;
  if (phi >= two_pi) phi = 0.0;
  return {x[0] - sense_ * time_function(r), r, th, phi};
}

Vec4 Kottler::scene_time_gradient(const Vec4& x) const {
  const double r = radius(x);
  const double dT = sense_ * (1.0 - lapse2(r)) / lapse2(r);
  return {1.0, -dT * x[1] / r, -dT * x[2] / r, -dT * x[3] / r};
}

Vec4 Kottler::scene_vector(const Vec4& x, const Vec4& v) const {
  const double r = radius(x);
  const Vec3 n = {x[1] / r, x[2] / r, x[3] / r};
  const double dr = n[0] * v[1] + n[1] * v[2] + n[2] * v[3];
  double dth, dphi;
  polar_angle_rates(x, v, r, dth, dphi);
  return {dot(scene_time_gradient(x), v), dr, dth, dphi};
}

std::array<Vec4, 4> Kottler::polar_basis(const Vec4& s) const {
  const double r = s[1], th = s[2], ph = s[3];
  const double sn = std::sin(th), cs = std::cos(th), sp = std::sin(ph), cp = std::cos(ph);
  const double dT = sense_ * (1.0 - lapse2(r)) / lapse2(r);
  return {Vec4{1.0, 0.0, 0.0, 0.0}, Vec4{dT, sn * cp, sn * sp, cs}, Vec4{0.0, r * cs * cp, r * cs * sp, -r * sn},
          Vec4{0.0, -r * sp, r * cp, 0.0}};
}

}  // namespace lc
