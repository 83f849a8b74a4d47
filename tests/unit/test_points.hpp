#pragma once
// Deterministic random sample points for the physics tests: a fixed seed so a
// failure is reproducible, many points so that a wrong sign anywhere shows.

#include <random>
#include <vector>

#include "core/tensor.hpp"

namespace lc::test {

// Cartesian points with radius in [rmin, rmax], including points near and on
// the z axis (where polar coordinates degenerate but the physics must not).
inline std::vector<Vec4> cartesian_points(int n, double rmin, double rmax, unsigned seed = 12345) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec4> pts;
  for (int i = 0; i < n; ++i) {
    const double r = rmin + (rmax - rmin) * u(rng);
    const double ct = i % 10 == 0 ? 1.0 - 1e-9 * u(rng) : 2.0 * u(rng) - 1.0;
    const double st = std::sqrt(std::max(0.0, 1.0 - ct * ct));
    const double ph = 6.283185307179586 * u(rng);
    pts.push_back({10.0 * u(rng), r * st * std::cos(ph), r * st * std::sin(ph), r * ct});
  }
  return pts;
}

inline std::vector<Vec4> momenta(int n, unsigned seed = 777) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec4> ps;
  for (int i = 0; i < n; ++i) ps.push_back({-1.0 + 0.3 * u(rng), u(rng), u(rng), u(rng)});
  return ps;
}

}  // namespace lc::test
