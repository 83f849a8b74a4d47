#pragma once
// The Novikov–Thorne thin accretion disk around a Kerr hole (Novikov &
// Thorne 1973; Page & Thorne 1974, ApJ 191, 499): the energy its surface
// radiates, per unit proper time and proper area of one face, in the frame
// of its orbiting matter, from a steady accretion rate and zero torque at
// the innermost stable circular orbit.  Geometric units (G = c = 1), and SI
// for a temperature; the disk co-rotates with the hole, so the flux depends
// on |a| only.

namespace lc {

class NovikovThorneFlux {
 public:
  // mass > 0, |spin| < mass; throws std::invalid_argument otherwise.
  NovikovThorneFlux(double mass, double spin);

  // Boyer–Lindquist radius of the innermost stable circular orbit
  // (co-rotating; Bardeen, Press & Teukolsky 1972).
  double isco_radius() const { return r_isco_; }

  // The flux F(r) in units of Mdot / M^2 (Mdot the rest-mass accretion
  // rate): Page & Thorne's closed form (their eq. 15n, in x = sqrt(r/M)),
  // 0 at and inside the ISCO.  Far out F -> 3 M Mdot / (8 pi r^3).
  double operator()(double r) const;

  // The radius where F is largest (golden-section search; to ~1e-9 M).
  double peak_radius() const;

  // The effective temperature (K) of the ring at r for a hole of
  // `solar_masses` (the physical mass the geometric mass stands for)
  // accreting `solar_masses_per_year`: sigma T^4 = F (Stefan–Boltzmann), F
  // in SI being F(r) Mdot c^2 / l^2 with l = G M / c^2 per unit of the
  // geometric mass.  Both rates > 0.
  double temperature(double r, double solar_masses, double solar_masses_per_year) const;

 private:
  double M_, a_;  // a_ = |spin| / mass
  double r_isco_, x0_;
  double x_[3];   // roots of x^3 - 3x + 2a = 0
  double c_[3];   // their terms' coefficients
};

}  // namespace lc
