#include "light/novikov_thorne.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/kerr_isco.hpp"

namespace lc {

NovikovThorneFlux::NovikovThorneFlux(double mass, double spin) : M_(mass) {
  if (!(mass > 0.0) || !std::isfinite(mass))
    throw std::invalid_argument(fmt::format("a Novikov–Thorne disk needs a hole of mass > 0, got {}", mass));
  if (!(std::abs(spin) < mass))
    throw std::invalid_argument(fmt::format(
        "a Novikov–Thorne disk needs |spin| < mass (at |spin| = mass its inner edge is on the horizon; Thorne's "
        "limit for accreting holes is 0.998 M), got spin {} for mass {}",
        spin, mass));
  a_ = std::abs(spin) / mass;
  r_isco_ = kerr_isco_radius(mass, spin);
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

double NovikovThorneFlux::operator()(double r) const {
  if (!(r > r_isco_)) return 0.0;
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
