#pragma once
// The names of hit kinds (core/hit_kind.hpp): the ends every scene has and
// each registered object kind's own (its Lua name), for `lightcone trace`
// and the docs.  The object registry's kinds must not share a value with
// each other or with the ends.

#include <array>
#include <string_view>

#include "core/hit_kind.hpp"
#include "objects/objects.hpp"

namespace lc {

namespace detail {
inline constexpr std::array<HitKind, 4> scene_end_kinds = {HitKind::sky, HitKind::horizon, HitKind::gave_up,
                                                           HitKind::no_ray};
template <class... O>
constexpr bool object_hit_kinds_are_distinct(Registry<O...>*) {
  constexpr std::array<HitKind, sizeof...(O)> kinds = {O::hit_kind...};
  for (std::size_t a = 0; a < kinds.size(); ++a) {
    for (std::size_t b = a + 1; b < kinds.size(); ++b)
      if (kinds[a] == kinds[b]) return false;
    for (const HitKind e : scene_end_kinds)
      if (kinds[a] == e) return false;
  }
  return true;
}
}  // namespace detail
static_assert(detail::object_hit_kinds_are_distinct(static_cast<ObjectRegistry*>(nullptr)),
              "every object kind needs a hit_kind of its own, none of core/hit_kind.hpp's");

// The name of hit kind k: "sky", "horizon", "gave up", "no ray", or the
// object kind's name; "unknown" for a value nothing has.
inline std::string_view hit_kind_name(HitKind k) {
  switch (k) {
    case HitKind::sky: return "sky";
    case HitKind::horizon: return "horizon";
    case HitKind::gave_up: return "gave up";
    case HitKind::no_ray: return "no ray";
  }
  std::string_view name = "unknown";
  ObjectRegistry::for_each([&](auto* kind) {
    using O = std::remove_pointer_t<decltype(kind)>;
    if (O::hit_kind == k) name = O::name;
  });
  return name;
}

}  // namespace lc
