#pragma once
// The registry of object kinds: every kind lightcone knows, one line each,
// each a class satisfying ObjectKind in its own files.  A scene holds what
// a shot gave (ObjectSpec: lc.<name>{...}), the built scene the objects,
// one list per kind (ObjectLists), so the ray's visitor loops over each
// kind's list with that kind's own test inlined: no call through a pointer.

#include <concepts>
#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <variant>
#include <vector>

#include "core/color.hpp"
#include "core/hit_kind.hpp"
#include "core/registry.hpp"
#include "objects/disk.hpp"
#include "objects/object_params.hpp"
#include "objects/surface_point.hpp"
#include "objects/sphere.hpp"
#include "objects/step_query.hpp"

namespace lc {

// What an object kind is, in the spacetime S (its trace chart): a name (its
// Lua constructor lc.<name>{...}), the hit.kind its hits are, whether the
// Boyer–Lindquist–Mino fast path handles it (render/kerr_fast_path_ray.hpp does, by
// kind; else a scene with one takes the general path), Params with declared
// fields, a constructor from them (with the shot's resources and the
// frame's observer event), how far it reaches in the spacetime's flight
// measure (for the free-flight radius: SpacetimeEnds::flight_reach), the first hit within a step (before the earliest
// found so far; objects/step_query.hpp), the 4-velocity of its matter where
// a ray meets it (trace chart; for hit.g), where on it a ray that ended at
// a trace event met it (surface_at: a SurfacePoint in its own coordinates,
// kept in the hit record) and its colour at such a point seen as the light
// model says (color_at; light/light.hpp).
template <class O, class S>
concept ObjectKind = requires(const O& o, const typename O::Params& p, const S& st, ShotResources& res, const Vec4& x,
                              StepTest& t, const RayState& y, std::size_t index) {
  requires std::same_as<std::remove_cv_t<decltype(O::name)>, std::string_view>;
  requires std::same_as<std::remove_cv_t<decltype(O::hit_kind)>, HitKind>;
  requires std::same_as<std::remove_cv_t<decltype(O::in_fast_path)>, bool>;
  requires HasFields<typename O::Params>;
  O(p, st, res, x);
  { o.reach(st) } -> std::same_as<double>;
  { o.first_hit(st, t, index) } -> std::same_as<std::optional<double>>;
  { o.surface_at(st, y) } -> std::same_as<SurfacePoint>;
  { o.color_at(SurfacePoint{}, SeenShift{}) } -> std::same_as<Color>;
  { o.emitter_velocity(st, y) } -> std::same_as<Vec4>;
};

// Every object kind, one line each.
using ObjectRegistry = Registry<Disk, Sphere>;

namespace detail {
template <class R>
struct ListsOf;
template <class... O>
struct ListsOf<Registry<O...>> {
  using type = std::tuple<std::vector<O>...>;
};
}  // namespace detail
// The object a shot asked for (objects/object_spec.hpp): the kinds'
// parameters, listed apart in the same order.
static_assert(std::is_same_v<ObjectRegistry::Spec, ObjectSpecs::Spec>,
              "objects/object_params.hpp must list the registered objects' Params in the registry's order");

// The built objects of a scene, one list per kind, in registry order.
using ObjectLists = detail::ListsOf<ObjectRegistry>::type;

// The same as a class, which render/scene.hpp names without including
// this registry: a scene holds its objects through a pointer to one, so
// what holds a scene is not rebuilt for a new object kind
// (docs/architecture.md, "What a new kind rebuilds").
struct ObjectSet {
  ObjectLists lists;
};

// f(object, index) for every object, kind by kind; index counts across all.
template <class F>
void for_each_object(const ObjectLists& lists, F&& f) {
  std::size_t index = 0;
  std::apply([&](const auto&... list) { ((void)[&] { for (const auto& o : list) f(o, index++); }(), ...); }, lists);
}

// The index for_each_object gives the i-th object of kind O.
template <class O>
std::size_t object_index(const ObjectLists& lists, std::size_t i) {
  std::size_t before = 0;
  bool past = false;
  std::apply(
      [&](const auto&... list) {
        ((past = past || std::is_same_v<typename std::decay_t<decltype(list)>::value_type, O>,
          before += past ? 0 : list.size()),
         ...);
      },
      lists);
  return before + i;
}

// f(object) for the object numbered `index` (for_each_object's numbering);
// nothing if there is none.
template <class F>
void with_object(const ObjectLists& lists, std::size_t index, F&& f) {
  bool found = false;
  std::apply(
      [&](const auto&... list) {
        ((void)[&] {
          if (found) return;
          if (index < list.size()) {
            f(list[index]);
            found = true;
          } else {
            index -= list.size();
          }
        }(), ...);
      },
      lists);
}

// The object of `spec` built and added to its kind's list.
template <class S>
void add_object(ObjectLists& lists, const ObjectSpec& spec, const S& st, ShotResources& res, const Vec4& observer) {
  std::visit(
      [&](const auto& p) {
        ObjectRegistry::for_each([&](auto* kind) {
          using O = std::remove_pointer_t<decltype(kind)>;
          if constexpr (std::is_same_v<typename O::Params, std::decay_t<decltype(p)>>)
            std::get<std::vector<O>>(lists).emplace_back(p, st, res, observer);
        });
      },
      spec.kinds());
}

// Whether the fast path handles every object the scene has.
inline bool objects_in_fast_path(const ObjectLists& lists) {
  bool ok = true;
  std::apply([&](const auto&... list) { ((ok = ok && (std::decay_t<decltype(list)>::value_type::in_fast_path || list.empty())), ...); },
             lists);
  return ok;
}

}  // namespace lc
