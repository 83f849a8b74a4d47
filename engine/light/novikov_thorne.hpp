#pragma once
// The Novikov–Thorne thin accretion disk around a Kerr hole (Novikov &
// Thorne 1973; Page & Thorne 1974, ApJ 191, 499): the energy its surface
// radiates, per unit proper time and proper area of one face, in the frame
// of its orbiting matter, from a steady accretion rate and zero torque at
// the innermost stable circular orbit.  Geometric units (G = c = 1), and SI
// for a temperature; the disk co-rotates with the hole, so the flux depends
// on |a| only.  Around a charged hole (Kerr–Newman; the disk's matter
// neutral) Page & Thorne's general integral is evaluated numerically over
// the circular orbits' E, L and Ω, for there is no closed form.

#include <vector>

namespace lc {

class NovikovThorneFlux {
 public:
  // mass > 0, spin^2 + charge^2 < mass^2; throws std::invalid_argument
  // otherwise.
  NovikovThorneFlux(double mass, double spin, double charge = 0.0);

  // Boyer–Lindquist radius of the innermost stable circular orbit
  // (co-rotating; Bardeen, Press & Teukolsky 1972; core/kerr_isco.hpp with
  // a charge).
  double isco_radius() const { return r_isco_; }

  // The flux F(r) in units of Mdot / M^2 (Mdot the rest-mass accretion
  // rate): Page & Thorne's closed form (their eq. 15n, in x = sqrt(r/M)),
  // 0 at and inside the ISCO.  Far out F -> 3 M Mdot / (8 pi r^3).  With a
  // charge, their general form (eq. 11b with eq. 12),
  //   F = -Ω' / (4π r (E - ΩL)^2) ∫_{r_isco}^{r} (E - ΩL) L' dr,
  // over Kerr–Newman's prograde circular orbits (page_thorne below).
  double operator()(double r) const;

  // The general form above at r, integrated afresh (8-point Gauss–Legendre
  // on panels spaced geometrically from the ISCO), whatever the charge: the
  // check of the tabulated path, and at Q = 0 of the closed form.
  double page_thorne(double r) const;

  // The radius where F is largest (golden-section search; to ~1e-9 M).
  double peak_radius() const;

  // The effective temperature (K) of the ring at r for a hole of
  // `solar_masses` (the physical mass the geometric mass stands for)
  // accreting `solar_masses_per_year`: sigma T^4 = F (Stefan–Boltzmann), F
  // in SI being F(r) Mdot c^2 / l^2 with l = G M / c^2 per unit of the
  // geometric mass.  Both rates > 0.
  double temperature(double r, double solar_masses, double solar_masses_per_year) const;

 private:
  // (E - ΩL) L' and what multiplies its integral, at r.
  double integrand(double r) const;
  double prefactor(double r) const;
  // ∫ integrand over [lo, hi], 8-point Gauss–Legendre on `panels` panels
  // spaced geometrically.
  double integral(double lo, double hi, int panels) const;

  double M_, a_;  // a_ = |spin| / mass
  double Q2_ = 0.0;  // charge^2, geometric units
  double r_isco_, x0_;
  double x_[3];   // roots of x^3 - 3x + 2a = 0
  double c_[3];   // their terms' coefficients
  // With a charge: the integral from the ISCO to node k of radii spaced
  // geometrically out to 1e6 M (kn_nodes_ apart in log r), for operator().
  std::vector<double> integral_at_node_;
  double log_r_isco_ = 0.0, log_step_ = 0.0;
};

}  // namespace lc
