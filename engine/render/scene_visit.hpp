#pragma once
// visit_scene(f, scene): f(scene.get<S>()) for the registered spacetime S
// the scene is in, for what does something in every spacetime (the
// renderer, the scene builder, `lightcone trace`).  It includes the list of
// spacetimes, so a new one rebuilds what includes this header
// (docs/architecture.md, "What a new kind rebuilds"); code for one spacetime
// reads scene.get<S>() instead.

#include <type_traits>
#include <utility>
#include <variant>

#include "render/scene.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace detail {
// f on the scene as the first of the spacetimes it can be in; the last one
// left is taken by get<>, which throws std::bad_variant_access for a scene
// in an unregistered spacetime (none is built).
template <class Scn, class F, class First, class... Rest>
decltype(auto) visit_scene_in(Scn& scene, F& f, std::variant<First, Rest...>*) {
  if constexpr (sizeof...(Rest) == 0) {
    return f(scene.template get<First>());
  } else {
    if (auto* sc = scene.template get_if<First>()) return f(*sc);
    return visit_scene_in(scene, f, static_cast<std::variant<Rest...>*>(nullptr));
  }
}
}  // namespace detail

template <class F>
decltype(auto) visit_scene(F&& f, const Scene& scene) {
  return detail::visit_scene_in(scene, f, static_cast<SpacetimeList*>(nullptr));
}
template <class F>
decltype(auto) visit_scene(F&& f, Scene& scene) {
  return detail::visit_scene_in(scene, f, static_cast<SpacetimeList*>(nullptr));
}

}  // namespace lc
