#pragma once
// What a thin disk's matter does in a spacetime: how it moves (its
// 4-velocity where a ray meets it, for hit.g: docs/light.md) and, where a
// thin-disk theory is worked out, how it glows (the Novikov–Thorne flux).
// A trait beside the disk (objects/disk.hpp), not a part of every
// spacetime: a spacetime with no disk theory writes no disk code, and a
// disk there is matter at rest in the trace chart that cannot glow (a
// glowing one is refused).  A spacetime with a theory has its
// specialization below.

#include <optional>

#include "core/tensor.hpp"
#include "light/novikov_thorne.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"

namespace lc {

template <class S>
struct DiskPhysics {
  static Vec4 velocity(const S&, const Vec4&) { return {1.0, 0.0, 0.0, 0.0}; }
  static std::optional<NovikovThorneFlux> flux(const S&) { return std::nullopt; }
};

// Kerr: circular equatorial geodesics (Kerr::disk_velocity) and the
// Novikov–Thorne flux from the ISCO outwards.
template <>
struct DiskPhysics<Kerr> {
  static Vec4 velocity(const Kerr& st, const Vec4& x) { return st.disk_velocity(x); }
  static std::optional<NovikovThorneFlux> flux(const Kerr& st) { return st.thin_disk_flux(); }
};

// Two holes: circular orbits in the symmetry plane (Dihole::disk_velocity);
// no flux is worked out, so a disk there cannot glow.
template <>
struct DiskPhysics<Dihole> {
  static Vec4 velocity(const Dihole& st, const Vec4& x) { return st.disk_velocity(x); }
  static std::optional<NovikovThorneFlux> flux(const Dihole&) { return std::nullopt; }
};

}  // namespace lc
