#pragma once
// A registry of kinds of one concept (cameras, skies, objects): the kinds,
// one line each, as Registry<K...>.  Each kind K is a class with a static
// `name` (its Lua constructor lc.<name>{...}) and a `Params` struct with
// declared fields (core/fields.hpp).  From that list come the variant of
// parameters a scene holds (Spec), the variant of built kinds (Kinds), the
// names, the exact key and the JSON of a spec, and building a kind from its
// spec: nothing else lists the kinds.  every_kind checks each kind of a
// list against its concept, one assertion per kind.

#include <array>
#include <string>
#include <string_view>
#include <variant>

#include <fmt/format.h>

#include "core/fields.hpp"

namespace lc {

template <class... K>
struct Registry {
  using Kinds = std::variant<K...>;
  using Spec = std::variant<typename K::Params...>;
  static constexpr std::array<std::string_view, sizeof...(K)> names = {K::name...};

  // The name of the kind a spec is for.
  static std::string_view name(const Spec& s) { return names[s.index()]; }

  // f(static_cast<K*>(nullptr)) for each kind, in registry order.
  template <class F>
  static void for_each(F&& f) {
    (f(static_cast<K*>(nullptr)), ...);
  }

  // "name field=value ...", exactly: what frames are compared by.  Every
  // declared field is in it (a placement too: core/fields.hpp,
  // KeyedByValue); a kind whose Params hold more than their declared fields
  // adds that with extra_key(), which nothing checks is there: declare a
  // field instead where its type allows.
  static std::string key(const Spec& s) {
    return std::string(name(s)) + std::visit(
                                      [](const auto& p) {
                                        std::string k = fields_key(p);
                                        if constexpr (requires { p.extra_key(); }) k += p.extra_key();
                                        return k;
                                      },
                                      s);
  }

  // {"kind": "name", <each field>: value}, and extra_json(polar) where a
  // kind has it (polar: whether the scene's positions are polar, for
  // fields holding one).
  static std::string json(const Spec& s, bool polar = false) {
    return fmt::format("{{\"kind\": \"{}\"{}}}", name(s), std::visit(
                                                              [polar](const auto& p) {
                                                                std::string j = fields_json(p, polar);
                                                                if constexpr (requires { p.extra_json(polar); })
                                                                  j += p.extra_json(polar);
                                                                return j;
                                                              },
                                                              s));
  }

  // The kind a spec is for, made from its parameters and `args`.
  template <std::size_t I = 0, class... Args>
  static Kinds build(const Spec& spec, Args&&... args) {
    using T = std::variant_alternative_t<I, Kinds>;
    if constexpr (I + 1 < sizeof...(K))
      if (spec.index() != I) return build<I + 1>(spec, static_cast<Args&&>(args)...);
    return T(std::get<I>(spec), static_cast<Args&&>(args)...);
  }
};

namespace detail {
template <template <class...> class List, class... K, class Check>
constexpr bool every_kind_of(List<K...>*, Check check) {
  (check.template operator()<K>(), ...);
  return true;
}
}  // namespace detail

// Calls check.template operator()<K>() for each kind K of `List` (a
// Registry<K...> or a std::variant<K...>), in order, and returns true: for
// a registry's one assertion of its concept, written as
//   static_assert(every_kind<CameraRegistry>([]<class C>() {
//     static_assert(CameraModel<C>, "a registered camera must satisfy CameraModel");
//   }));
// A concept cannot be a template argument, so the check is a lambda with
// the static_assert inside: the compiler then instantiates it once per
// kind, and its notes name the kind ("with C = ...") and the requirement
// it misses ("the required expression '...' is invalid").
template <class List, class Check>
constexpr bool every_kind(Check check) {
  return detail::every_kind_of(static_cast<List*>(nullptr), check);
}

}  // namespace lc
