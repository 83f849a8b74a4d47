#pragma once
// What a thin disk's matter does in a spacetime: how it moves (its
// 4-velocity where a ray meets it, for hit.g: docs/light.md) — as matter in
// the equatorial plane moves there (spacetime/equatorial_flow.hpp) — and,
// where a thin-disk theory is worked out, how it glows (the Novikov–Thorne
// flux).  A trait beside the disk (objects/disk.hpp), not a part of every
// spacetime: a spacetime with no disk theory writes no disk code, and a
// disk there cannot glow (a glowing one is refused).  A spacetime with a
// theory has its specialization below.

#include <optional>

#include "core/tensor.hpp"
#include "light/novikov_thorne.hpp"
#include "spacetime/equatorial_flow.hpp"
#include "spacetime/kerr.hpp"

namespace lc {

template <class S>
struct DiskPhysics {
  static Vec4 velocity(const S& st, const Vec4& x) { return EquatorialFlow<S>::velocity(st, x); }
  static std::optional<NovikovThorneFlux> flux(const S&) { return std::nullopt; }
};

// Kerr and Kerr–Newman: the Novikov–Thorne flux from the ISCO outwards
// (Kerr::thin_disk_flux).
template <>
struct DiskPhysics<Kerr> {
  static Vec4 velocity(const Kerr& st, const Vec4& x) { return EquatorialFlow<Kerr>::velocity(st, x); }
  static std::optional<NovikovThorneFlux> flux(const Kerr& st) { return st.thin_disk_flux(); }
};

}  // namespace lc
