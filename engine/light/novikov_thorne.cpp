#include "light/novikov_thorne.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/kerr_isco.hpp"

namespace lc {

namespace {

// Nodes of the charged disk's table: geometric from the ISCO to 1e6 M.
constexpr int table_nodes = 1024;
constexpr double table_reach = 1e6;

// 8-point Gauss–Legendre nodes and weights on [-1, 1] (Abramowitz & Stegun
// table 25.4).
constexpr double gl_x[4] = {0.183434642495649805, 0.525532409916328986, 0.796666477413626740, 0.960289856497536232};
constexpr double gl_w[4] = {0.362683783378361983, 0.313706645877887287, 0.222381034453374471, 0.101228536290376259};

// A prograde circular equatorial orbit of neutral matter about a
// Kerr–Newman hole (M, a >= 0, Q^2) at Boyer–Lindquist r: its energy and
// angular momentum per unit mass and its angular velocity (Dadhich & Kale,
// J. Math. Phys. 18, 1727 (1977); Kerr's at Q = 0, Bardeen, Press &
// Teukolsky 1972, eqs. 2.12–2.13, 2.16).
struct CircularOrbit {
  double E, L, Omega;
};
CircularOrbit circular_orbit(double M, double a, double Q2, double r) {
  const double s = std::sqrt(M * r - Q2);
  const double D = r * std::sqrt(r * r - 3.0 * M * r + 2.0 * Q2 + 2.0 * a * s);
  return {(r * r - 2.0 * M * r + Q2 + a * s) / D, (s * (r * r + a * a) - a * (2.0 * M * r - Q2)) / D,
          s / (r * r + a * s)};
}

}  // namespace

NovikovThorneFlux::NovikovThorneFlux(double mass, double spin, double charge) : M_(mass), Q2_(charge * charge) {
  if (!(mass > 0.0) || !std::isfinite(mass))
    throw std::invalid_argument(fmt::format("a Novikov–Thorne disk needs a hole of mass > 0, got {}", mass));
  if (!(spin * spin + charge * charge < mass * mass))
    throw std::invalid_argument(fmt::format(
        "a Novikov–Thorne disk needs spin^2 + charge^2 < mass^2 (in the extreme case its inner edge is on the "
        "horizon; Thorne's limit for accreting holes is |spin| = 0.998 M), got spin {}, charge {} for mass {}",
        spin, charge, mass));
  a_ = std::abs(spin) / mass;
  r_isco_ = kerr_newman_isco_radius(mass, spin, charge);
  if (Q2_ > 0.0) {
    // The table: node k at r_isco e^(k step); each stretch integrated on
    // its own (the integrand is smooth, ~(r - r_isco) at the ISCO).
    log_r_isco_ = std::log(r_isco_);
    log_step_ = std::log(table_reach * M_ / r_isco_) / (table_nodes - 1);
    integral_at_node_.assign(table_nodes, 0.0);
    for (int k = 1; k < table_nodes; ++k)
      integral_at_node_[k] = integral_at_node_[k - 1] +
                             integral(std::exp(log_r_isco_ + (k - 1) * log_step_), std::exp(log_r_isco_ + k * log_step_), 1);
  }
  x0_ = std::sqrt(r_isco_ / M_);
  const double third = std::acos(a_) / 3.0;
  x_[0] = 2.0 * std::cos(third - pi / 3.0);
  x_[1] = 2.0 * std::cos(third + pi / 3.0);
  x_[2] = -2.0 * std::cos(third);
  for (int i = 0; i < 3; ++i) {
    const double xi = x_[i], xj = x_[(i + 1) % 3], xk = x_[(i + 2) % 3];
    // At a = 0 the root x = 0 has coefficient (x - a)^2 / x -> 0.
    c_[i] = xi == 0.0 ? 0.0 : 3.0 * (xi - a_) * (xi - a_) / (xi * (xi - xj) * (xi - xk));
  }
}

double NovikovThorneFlux::integrand(double r) const {
  const double a = a_ * M_, h = 1e-6 * r;
  const CircularOrbit o = circular_orbit(M_, a, Q2_, r);
  // L' by central differences: truncation ~(h/r)^2 = 1e-12, rounding ~1e-10.
  const double dL = (circular_orbit(M_, a, Q2_, r + h).L - circular_orbit(M_, a, Q2_, r - h).L) / (2.0 * h);
  return (o.E - o.Omega * o.L) * dL;
}

double NovikovThorneFlux::prefactor(double r) const {
  const double a = a_ * M_, h = 1e-6 * r;
  const CircularOrbit o = circular_orbit(M_, a, Q2_, r);
  const double dOmega =
      (circular_orbit(M_, a, Q2_, r + h).Omega - circular_orbit(M_, a, Q2_, r - h).Omega) / (2.0 * h);
  const double k = o.E - o.Omega * o.L;
  // √(-g) of the (t, r, φ) metric in the equatorial plane: r
  // (Boyer–Lindquist, Kerr–Newman as Kerr: g_tt g_φφ - g_tφ^2 = -Δ,
  // g_rr = r^2/Δ).
  return -dOmega / (4.0 * pi * r * k * k);
}

double NovikovThorneFlux::integral(double lo, double hi, int panels) const {
  double sum = 0.0;
  const double ratio = std::pow(hi / lo, 1.0 / panels);
  double a = lo;
  for (int p = 0; p < panels; ++p) {
    const double b = p + 1 == panels ? hi : a * ratio, mid = 0.5 * (a + b), half = 0.5 * (b - a);
    for (int i = 0; i < 4; ++i)
      sum += half * gl_w[i] * (integrand(mid - half * gl_x[i]) + integrand(mid + half * gl_x[i]));
    a = b;
  }
  return sum;
}

double NovikovThorneFlux::page_thorne(double r) const {
  if (!(r > r_isco_)) return 0.0;
  return prefactor(r) * integral(r_isco_, r, 64);
}

double NovikovThorneFlux::operator()(double r) const {
  if (!(r > r_isco_)) return 0.0;
  if (Q2_ > 0.0) {
    // From the node below r (the last, beyond the table's reach).
    const int k = std::min(table_nodes - 1, static_cast<int>((std::log(r) - log_r_isco_) / log_step_));
    const double node = std::exp(log_r_isco_ + k * log_step_);
    return prefactor(r) * (integral_at_node_[k] + (r > node ? integral(node, r, 1) : 0.0));
  }
  const double x = std::sqrt(r / M_);
  double bracket = x - x0_ - 1.5 * a_ * std::log(x / x0_);
  for (int i = 0; i < 3; ++i)
    if (c_[i] != 0.0) bracket -= c_[i] * std::log((x - x_[i]) / (x0_ - x_[i]));
  const double x2 = x * x;
  return 3.0 / (8.0 * pi * M_ * M_) * bracket / (x2 * x2 * (x2 * x - 3.0 * x + 2.0 * a_));
}

double NovikovThorneFlux::peak_radius() const {
  // F rises from 0 at the ISCO and falls as r^-3 far out: one maximum,
  // within (r_isco, 10 r_isco) (Schwarzschild: 9.55 M, r_isco 6 M).
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = r_isco_, hi = 10.0 * r_isco_;
  double m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
  double f1 = (*this)(m1), f2 = (*this)(m2);
  while (hi - lo > 1e-9 * M_) {
    if (f1 < f2) {
      lo = m1;
      m1 = m2;
      f1 = f2;
      m2 = lo + g * (hi - lo);
      f2 = (*this)(m2);
    } else {
      hi = m2;
      m2 = m1;
      f2 = f1;
      m1 = hi - g * (hi - lo);
      f1 = (*this)(m1);
    }
  }
  return 0.5 * (lo + hi);
}

double NovikovThorneFlux::temperature(double r, double solar_masses, double solar_masses_per_year) const {
  const double metres = gravitational_constant * solar_masses * solar_mass / (speed_of_light * speed_of_light) / M_;
  const double mdot = solar_masses_per_year * solar_mass / julian_year;  // kg / s
  const double flux = (*this)(r) * mdot * speed_of_light * speed_of_light / (metres * metres);  // W / m^2
  return std::sqrt(std::sqrt(flux / stefan_boltzmann));
}

}  // namespace lc
