#include "spacetime/kerr.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/kerr_isco.hpp"

namespace lc {

namespace {

// f, l_mu and their spatial gradients at a Kerr–Schild point (off the hot
// path; hamiltonian_rhs inlines the same algebra).
struct KerrSchildFields {
  double f;
  Vec4 l;                     // l_mu, lower index, l_t = 1
  std::array<double, 3> df;   // ∂_j f, j = x, y, z
  std::array<Vec4, 3> dl;     // dl[j][mu] = ∂_j l_mu
};

// a: the chart's signed spin; Q2: the charge squared; lt: l_t (+1 ingoing,
// -1 outgoing).
KerrSchildFields fields(double M, double a, double Q2, double lt, double r, const Vec4& x) {
  const double X = x[1], Y = x[2], Z = x[3];
  const double a2 = a * a, r2 = r * r;
  const double q = 1.0 / (r2 + a2);
  const double den = 1.0 / (r2 * r2 + a2 * Z * Z);
  KerrSchildFields F{};
  const double n = 2.0 * M * r2 * r - Q2 * r2;  // (2 M r - Q^2) r^2
  F.f = n * den;
  F.l = {lt, (r * X + a * Y) * q, (r * Y - a * X) * q, Z / r};
  const std::array<double, 3> dr = {X * r2 * r * den, Y * r2 * r * den, Z * (r2 + a2) * r * den};
  const double dfdr = (2.0 * M * r2 * (3.0 * a2 * Z * Z - r2 * r2) + 2.0 * Q2 * r * (r2 * r2 - a2 * Z * Z)) * den * den;
  const double dfdz = -2.0 * n * a2 * Z * den * den;
  for (int j = 0; j < 3; ++j) {
    const double dX = j == 0, dY = j == 1, dZ = j == 2;
    F.df[j] = dfdr * dr[j] + (j == 2 ? dfdz : 0.0);
    F.dl[j][0] = 0.0;
    F.dl[j][1] = (dr[j] * X + r * dX + a * dY) * q - F.l[1] * 2.0 * r * q * dr[j];
    F.dl[j][2] = (dr[j] * Y + r * dY - a * dX) * q - F.l[2] * 2.0 * r * q * dr[j];
    F.dl[j][3] = dZ / r - F.l[3] / r * dr[j];
  }
  return F;
}

}  // namespace

Kerr::Kerr(double mass, double spin, double charge, KerrSchildSense sense)
    : M_(mass), a_(spin), Q_(charge), Q2_(charge * charge), sense_(sense == KerrSchildSense::ingoing ? 1.0 : -1.0),
      ak_(sense_ * spin) {
  if (!std::isfinite(mass) || !std::isfinite(spin) || !std::isfinite(charge))
    throw std::invalid_argument("kerr: mass, spin and charge must be finite numbers");
  if (mass < 0.0) throw std::invalid_argument(fmt::format("kerr: mass must be >= 0, got {}", mass));
  if (charge == 0.0 && std::abs(spin) > mass)
    throw std::invalid_argument(fmt::format(
        "kerr: |spin| must not exceed the mass (|a| <= M), got a = {} with M = {}", spin, mass));
  // A few ulps of slack: an extremal hole written as charge = sqrt(1 - a^2)
  // may round above M^2 (it is then extremal: r_+ = r_- = M).
  if (spin * spin + Q2_ > mass * mass * (1.0 + 4.0 * std::numeric_limits<double>::epsilon()))
    throw std::invalid_argument(fmt::format(
        "kerr: spin and charge must satisfy a^2 + Q^2 <= M^2 (beyond it there is no horizon: a naked "
        "singularity), got a = {}, Q = {} with M = {} (a^2 + Q^2 = {:.6g})",
        spin, charge, mass, spin * spin + Q2_));
  if (M_ > 0.0) {
    const double root = std::sqrt(std::max(0.0, M_ * M_ - a_ * a_ - Q2_));
    r_plus_ = M_ + root;
    r_minus_ = M_ - root;
    r_capture_ =
        std::max(r_plus_ + kerr_capture_fraction * (photon_orbit_radius(true) - r_plus_), r_plus_ * (1.0 + 1e-3));
    r_isco_ = kerr_newman_isco_radius(M_, a_, Q_);
  }
}

double Kerr::photon_orbit_radius(bool prograde) const {
  if (!(M_ > 0.0)) return 0.0;
  // Kerr's closed form (Bardeen, Press & Teukolsky 1972, ApJ 178, 347, eq. 2.18).
  if (Q2_ == 0.0) return 2.0 * M_ * (1.0 + std::cos(2.0 / 3.0 * std::acos((prograde ? -1.0 : 1.0) * std::abs(a_) / M_)));
  return kerr_newman_photon_orbit_radius(M_, prograde ? std::abs(a_) : -std::abs(a_), Q_);
}

Mat4 Kerr::metric(const Vec4& x) const {
  Mat4 g = minkowski_metric;
  if (M_ == 0.0) return g;
  const auto F = fields(M_, ak_, Q2_, sense_, bl_radius(x[1], x[2], x[3]), x);
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) g[m][n] += F.f * F.l[m] * F.l[n];
  return g;
}

Mat4 Kerr::inverse_metric(const Vec4& x) const {
  Mat4 g = minkowski_metric;
  if (M_ == 0.0) return g;
  const auto F = fields(M_, ak_, Q2_, sense_, bl_radius(x[1], x[2], x[3]), x);
  const Vec4 lu = {-F.l[0], F.l[1], F.l[2], F.l[3]};  // l^mu = eta^{mu nu} l_nu
  for (int m = 0; m < 4; ++m)
    for (int n = 0; n < 4; ++n) g[m][n] -= F.f * lu[m] * lu[n];
  return g;
}

Mat4Derivs Kerr::metric_derivatives(const Vec4& x) const {
  Mat4Derivs d{};
  if (M_ == 0.0) return d;
  const auto F = fields(M_, ak_, Q2_, sense_, bl_radius(x[1], x[2], x[3]), x);
  for (int j = 0; j < 3; ++j)
    for (int m = 0; m < 4; ++m)
      for (int n = 0; n < 4; ++n)
        d[j + 1][m][n] = F.df[j] * F.l[m] * F.l[n] + F.f * (F.dl[j][m] * F.l[n] + F.l[m] * F.dl[j][n]);
  return d;
}

Vec4 Kerr::disk_velocity_bl(double r) const {
  if (!(M_ > 0.0)) return {1.0, 0.0, 0.0, 0.0};
  // The equatorial (t, phi) block of the BL metric at r, and its inverse
  // (g_tt g_phiphi - g_tphi^2 = -Delta there).
  struct Block {
    double tt, tp, pp;
  };
  // 2 m(r) = 2 M - Q^2 / r stands for 2 M in Kerr's equatorial formulas.
  const auto metric_at = [&](double rr) {
    const double two_m = 2.0 * M_ - Q2_ / rr;
    return Block{-(1.0 - two_m / rr), -two_m * a_ / rr, rr * rr + a_ * a_ + two_m * a_ * a_ / rr};
  };
  const auto circular = [&](double rr) {
    // Co-rotating: the sign of the spin (a = 0 counts as +).  Kerr–Newman:
    // Omega = s sqrt(M r - Q^2) / (r^2 + |a| sqrt(M r - Q^2)), Kerr's closed
    // form at Q = 0.
    const double s = a_ < 0.0 ? -1.0 : 1.0, sm = std::sqrt(M_);
    const double omega = Q2_ == 0.0 ? s * sm / (rr * std::sqrt(rr) + std::abs(a_) * sm)
                                    : s * std::sqrt(M_ * rr - Q2_) / (rr * rr + std::abs(a_) * std::sqrt(M_ * rr - Q2_));
    const Block g = metric_at(rr);
    const double ut = 1.0 / std::sqrt(-(g.tt + 2.0 * omega * g.tp + omega * omega * g.pp));
    return Vec4{ut, 0.0, 0.0, omega * ut};
  };
  const double r_isco = isco_radius();
  if (r >= r_isco) return circular(r);
  const Vec4 ui = circular(r_isco);
  const Block gi = metric_at(r_isco);
  const double u_t = gi.tt * ui[0] + gi.tp * ui[3], u_phi = gi.tp * ui[0] + gi.pp * ui[3];
  const Block g = metric_at(r);
  const double delta = r * r - 2.0 * M_ * r + a_ * a_ + Q2_;
  const double ut = (-g.pp * u_t + g.tp * u_phi) / delta, uphi = (g.tp * u_t - g.tt * u_phi) / delta;
  // u_mu u^mu = -1 with u^r < 0 (falling in), g_rr = r^2 / Delta.
  const double ur2 = (-1.0 - u_t * ut - u_phi * uphi) * delta / (r * r);
  return {ut, -std::sqrt(std::max(ur2, 0.0)), 0.0, uphi};
}

Vec4 Kerr::disk_velocity(const Vec4& x) const {
  const Vec4 s = scene_from_trace(x);
  const Vec4 u = disk_velocity_bl(s[1]);
  const Mat4 J = trace_jacobian(s);
  Vec4 out{};
  for (int mu = 0; mu < 4; ++mu)
    for (int nu = 0; nu < 4; ++nu) out[mu] += J[mu][nu] * u[nu];
  return out;
}

Mat4 Kerr::bl_metric(const Vec4& s) const {
  const double r = s[1], th = s[2];
  const double sn = std::sin(th), cs = std::cos(th);
  const double sigma = r * r + a_ * a_ * cs * cs;
  const double delta = r * r - 2.0 * M_ * r + a_ * a_ + Q2_;
  // Kerr's terms in Kerr's order, the charge's beside them (exact zeros at
  // Q = 0: the fast path's light split reads this metric).
  Mat4 g{};
  g[0][0] = -(1.0 - (2.0 * M_ * r - Q2_) / sigma);
  g[0][3] = g[3][0] = (-2.0 * M_ * a_ * r + Q2_ * a_) * sn * sn / sigma;
  g[1][1] = sigma / delta;
  g[2][2] = sigma;
  g[3][3] = (r * r + a_ * a_ + (2.0 * M_ * a_ * a_ * r - Q2_ * a_ * a_) * sn * sn / sigma) * sn * sn;
  return g;
}

double kerr_radial_time(double M, double a, double Q, double r) {
  if (M == 0.0) return 0.0;
  const double Q2 = Q * Q;
  const double root = std::sqrt(std::max(0.0, M * M - a * a - Q2)), rp = M + root, rm = M - root;
  if (rp - rm < 1e-8 * M)  // extremal limit of the expressions below
    return 2.0 * M * std::log(std::abs(r - M)) - (2.0 * M * M - Q2) / (r - M);
  if (Q2 == 0.0)  // Kerr's form of the one below (2 M r_+- = r_+-^2 + a^2 there)
    return 2.0 * M / (rp - rm) * (rp * std::log(std::abs(r - rp)) - rm * std::log(std::abs(r - rm)));
  // Partial fractions of (2 M r - Q^2) / ((r - r_+)(r - r_-)).
  return ((2.0 * M * rp - Q2) * std::log(std::abs(r - rp)) - (2.0 * M * rm - Q2) * std::log(std::abs(r - rm))) /
         (rp - rm);
}

// sense * T(r), and Phi(r) = sense * ∫ a / Delta dr.
double Kerr::time_shift(double r) const { return sense_ * kerr_radial_time(M_, a_, Q_, r); }

double Kerr::phi_shift(double r) const {
  if (M_ == 0.0 || a_ == 0.0) return 0.0;
  const double split = r_plus_ - r_minus_;
  if (split < 1e-8 * M_) return -ak_ / (r - M_);
  return ak_ / split * std::log(std::abs((r - r_plus_) / (r - r_minus_)));
}

Vec4 Kerr::trace_from_scene(const Vec4& s) const {
  const double r = s[1], th = s[2];
  const double phit = s[3] + phi_shift(r);
  const double sn = std::sin(th);
  return {s[0] + time_shift(r), sn * (r * std::cos(phit) - ak_ * std::sin(phit)),
          sn * (r * std::sin(phit) + ak_ * std::cos(phit)), r * std::cos(th)};
}

Vec4 Kerr::scene_from_trace(const Vec4& x) const {
  const double r = bl_radius(x[1], x[2], x[3]);
  const double th = r > 0.0 ? std::acos(std::clamp(x[3] / r, -1.0, 1.0)) : 0.5 * pi;
  double phi = std::atan2(x[2], x[1]) - std::atan2(ak_, r) - phi_shift(r);
  phi = std::fmod(phi, two_pi);
  if (phi < 0.0) phi += two_pi;
  if (phi >= two_pi) phi = 0.0;  // -tiny + 2 pi rounds to 2 pi
  return {x[0] - time_shift(r), r, th, phi};
}

Mat4 Kerr::trace_jacobian(const Vec4& s) const {
  const double r = s[1], th = s[2];
  const double delta = r * r - 2.0 * M_ * r + a_ * a_ + Q2_;
  const double dT = sense_ * (2.0 * M_ * r - Q2_) / delta, dPhi = ak_ / delta;
  const double phit = s[3] + phi_shift(r);
  const double sn = std::sin(th), cs = std::cos(th), sp = std::sin(phit), cp = std::cos(phit);
  const double a = ak_;  // the chart's signed spin
  const double X = sn * (r * cp - a * sp), Y = sn * (r * sp + a * cp);
  Mat4 J{};
  J[0][0] = 1.0;
  J[0][1] = dT;
  J[1][1] = sn * cp - Y * dPhi;
  J[1][2] = cs * (r * cp - a * sp);
  J[1][3] = -Y;
  J[2][1] = sn * sp + X * dPhi;
  J[2][2] = cs * (r * sp + a * cp);
  J[2][3] = X;
  J[3][1] = cs;
  J[3][2] = -r * sn;
  return J;
}

Vec4 Kerr::scene_vector(const Vec4& x, const Vec4& v) const {
  const Vec4 s = scene_from_trace(x);
  if (std::sin(s[2]) > 1e-9) return mat_vec(inverse(trace_jacobian(s)), v);
  // On the axis the BL chart degenerates (phi is undefined): report dt, dr
  // from their gradients, d(theta) as the rate of leaving the axis (cylindrical
  // radius ~ sqrt(r^2 + a^2) theta there) and d(phi) = 0.
  const double r = s[1];
  const double a2 = a_ * a_, r2 = r * r, Z = x[3];
  const double den = 1.0 / (r2 * r2 + a2 * Z * Z);
  const double dr = (x[1] * v[1] + x[2] * v[2]) * r2 * r * den + Z * (r2 + a2) * r * den * v[3];
  const double dth = std::sqrt(v[1] * v[1] + v[2] * v[2]) / std::sqrt(r2 + a2);
  return {dot(scene_time_gradient(x), v), dr, dth, 0.0};
}

Vec4 Kerr::scene_time_gradient(const Vec4& x) const {
  const double r = bl_radius(x[1], x[2], x[3]);
  if (M_ == 0.0) return {1.0, 0.0, 0.0, 0.0};
  const double a2 = a_ * a_, r2 = r * r, Z = x[3];
  const double den = 1.0 / (r2 * r2 + a2 * Z * Z);
  const double dT = sense_ * (2.0 * M_ * r - Q2_) / (r2 - 2.0 * M_ * r + a2 + Q2_);
  return {1.0, -dT * x[1] * r2 * r * den, -dT * x[2] * r2 * r * den, -dT * Z * (r2 + a2) * r * den};
}

std::array<Vec4, 4> Kerr::polar_basis(const Vec4& s) const {
  const Mat4 J = trace_jacobian(s);
  const double r = s[1];
  const double phit = s[3] + phi_shift(r);
  const double sp = std::sin(phit), cp = std::cos(phit);
  return {Vec4{1.0, 0.0, 0.0, 0.0}, Vec4{J[0][1], J[1][1], J[2][1], J[3][1]},
          Vec4{J[0][2], J[1][2], J[2][2], J[3][2]}, Vec4{0.0, -(r * sp + ak_ * cp), r * cp - ak_ * sp, 0.0}};
}

}  // namespace lc
