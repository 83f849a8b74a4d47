#pragma once
// How matter in a spacetime's equatorial plane (z = 0) moves, where that is
// worked out: on circular orbits about the z axis where they are stable,
// plunging from the innermost one inside it.  A trait beside the
// spacetimes, not a part of every one: a spacetime without it writes
// nothing, and matter there is at rest in the trace chart (`orbits` false).
// A thin disk's matter moves so (objects/disk_physics.hpp), and an observer
// may ride the circular orbits (observers/circular_orbit.hpp).

#include <cmath>

#include "core/tensor.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"

namespace lc {

// velocity(st, x): the matter's 4-velocity at the trace event x in the
// plane; orbits: whether it is on circular orbits (somewhere).  Elsewhere
// the matter is at rest in the trace chart: u = ∂_t / sqrt(-g_tt) (for a
// chart whose ∂_t is timelike there, as a static spacetime's is outside
// its horizons).
template <class S>
struct EquatorialFlow {
  static constexpr bool orbits = false;
  static Vec4 velocity(const S& st, const Vec4& x) { return {1.0 / std::sqrt(-st.metric(x)[0][0]), 0.0, 0.0, 0.0}; }
};

// Kerr and Kerr–Newman: Keplerian orbits co-rotating with the hole outside
// the ISCO, the plunge inside (Kerr::disk_velocity).
template <>
struct EquatorialFlow<Kerr> {
  static constexpr bool orbits = true;
  static Vec4 velocity(const Kerr& st, const Vec4& x) { return st.disk_velocity(x); }
};

// Two holes: circular orbits about their axis in the plane z = 0
// (Dihole::disk_velocity), at rest where none exists.
template <>
struct EquatorialFlow<Dihole> {
  static constexpr bool orbits = true;
  static Vec4 velocity(const Dihole& st, const Vec4& x) { return st.disk_velocity(x); }
};

}  // namespace lc
