#pragma once
// The ends of a spacetime: where a ray traced from the camera can go and
// not come back.  Each spacetime lists its own (S::ends), says which one a
// ray has reached in its own chart (S::flight, asked by the ray loop after
// every step: geodesic/ray_loop.hpp) and where an observer may stand
// (S::why_no_observer).  A ray captured by a horizon is the ray loop's
// capture rule (S::captured); a ray that reached any other end has escaped
// there and sees that end's sky (render/scene.hpp: SceneIn::sky_of).
//
// Most spacetimes have one far end, infinity, reached where the Cartesian
// radius of the trace chart grows past the escape radius:
// CartesianInfinity below says so once.  A wormhole has two infinities, one
// on each side of its throat; de Sitter space a cosmological horizon.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace lc {

enum class EndKind {
  infinity,              // a ray that gets there has escaped: the sky of that end
  cosmological_horizon,  // likewise, at a finite radius (the sky on it is what that end shows)
  horizon,               // an event horizon: the ray is captured (black)
};

constexpr std::string_view to_string(EndKind k) {
  switch (k) {
    case EndKind::infinity: return "infinity";
    case EndKind::cosmological_horizon: return "cosmological horizon";
    case EndKind::horizon: return "horizon";
  }
  return "unknown";
}

// One end as a spacetime declares it: its name (in `trace`, messages and
// the docs) and kind.
struct SpacetimeEnd {
  std::string_view name;
  EndKind kind;
};

// Whether a ray can leave by an end and see a sky there.
constexpr bool is_far(EndKind k) { return k != EndKind::horizon; }

// The index in S::ends of the first end of kind k; S::ends.size() if none.
template <class S>
constexpr std::size_t end_index(EndKind k) {
  for (std::size_t i = 0; i < S::ends.size(); ++i)
    if (S::ends[i].kind == k) return i;
  return S::ends.size();
}

// What a spacetime's list of ends must be: not empty, at most 255 ends (a
// record keeps the index in a byte), and the first a far end, where the
// scene's one sky is (each further far end may have its own).
template <class S>
constexpr bool ends_are_well_formed() {
  return !S::ends.empty() && S::ends.size() < 255 && is_far(S::ends[0].kind);
}

// Where a ray moving on is, as the ray loop asks after each step
// (geodesic/ray_loop.hpp, rules 5 and 6).
struct Flight {
  bool free = false;     // beyond everything it could meet: relax its tolerances
  bool escaped = false;  // it has reached a far end: done
  std::uint8_t end = 0;  // which one (an index in S::ends) when escaped
};

// A state's components as flight() reads them, for one ray held in an
// array (the spacetime concept's check, lightcone geodesic).
struct StateComponents {
  const std::array<double, 8>* y;
  double operator()(std::size_t j) const { return (*y)[j]; }
};

// The radii a scene gives the far-end rule, squared, in the spacetime's
// own radial measure (RayOptions::free_radius and escape_radius): where a
// ray meets nothing more and where it counts as arrived.  The measure is
// each spacetime's (the trace chart's Cartesian radius for
// CartesianInfinity, the proper distance |l| from a wormhole's throat):
// what reaches how far in it — objects, photon orbits — is asked of the
// spacetime (S::flight_reach), never compared with a chart radius by hand.
struct FlightRadii {
  double free2 = 1e300, escape2 = 1e300;
};

// The one far end of an asymptotically flat spacetime traced in a
// Cartesian-like chart (Minkowski, Kerr–Schild, the dihole's isotropic
// chart): infinity, reached beyond the escape radius moving outwards
// (x . dx > 0).  End 0 of S::ends must be that infinity.
struct CartesianInfinity {
  // y(j), dy(j): component j of the state (x^mu, p_mu) and of its slope.
  template <class Y, class D>
  static Flight flight(const Y& y, const D& dy, const FlightRadii& radii) {
    const double rho2 = y(1) * y(1) + y(2) * y(2) + y(3) * y(3);
    if (!(rho2 > radii.free2) && !(rho2 > radii.escape2)) return {};  // the slope is not read
    const bool outward = y(1) * dy(1) + y(2) * dy(2) + y(3) * dy(3) > 0.0;
    return {rho2 > radii.free2 && outward, rho2 > radii.escape2 && outward, 0};
  }
  // A source at rest far away is at rest in the trace chart, where
  // g_tt -> -1: the sky's light is measured against it as it is.
  static double sky_source_lapse(std::size_t) { return 1.0; }
  // The measure is the Cartesian radius itself: over the shell
  // lo <= |x| <= hi its largest value is hi.
  static double flight_reach(double, double hi) { return hi; }
};

}  // namespace lc
