#pragma once
// A registry of kinds of one concept (cameras, skies, objects): the kinds,
// one line each, as Registry<K...>.  Each kind K is a class with a static
// `name` (its Lua constructor lc.<name>{...}) and a `Params` struct with
// declared fields (core/fields.hpp).  From that list come the variant of
// parameters a scene holds (Spec), the variant of built kinds (Kinds), the
// names, the exact key and the JSON of a spec, and building a kind from its
// spec: nothing else lists the kinds but a SpecRegistry of their Params,
// where a registry keeps those apart (cameras).  every_kind checks each kind of a
// list against its concept, one assertion per kind.

#include <array>
#include <string>
#include <string_view>
#include <variant>

#include <fmt/format.h>

#include "core/fields.hpp"

namespace lc {

// "name field=value ...", exactly, of spec `s` whose kinds are named
// `names` in the variant's order: what frames are compared by.  Every
// declared field is in it (a placement too: core/fields.hpp,
// KeyedByValue); a kind whose Params hold more than their declared fields
// adds that with extra_key(), which nothing checks is there: declare a
// field instead where its type allows.
template <class Spec, std::size_t N>
std::string spec_key(const std::array<std::string_view, N>& names, const Spec& s) {
  return std::string(names[s.index()]) + std::visit(
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
template <class Spec, std::size_t N>
std::string spec_json(const std::array<std::string_view, N>& names, const Spec& s, bool polar) {
  return fmt::format("{{\"kind\": \"{}\"{}}}", names[s.index()], std::visit(
                                                                      [polar](const auto& p) {
                                                                        std::string j = fields_json(p, polar);
                                                                        if constexpr (requires { p.extra_json(polar); })
                                                                          j += p.extra_json(polar);
                                                                        return j;
                                                                      },
                                                                      s));
}

// The parameters of a registry's kinds alone, one line each, each P with
// a static `name` (its Lua constructor's): the variant a scene holds
// (Spec), the names, the key and the JSON of a spec.  Apart from the kinds
// (Registry below) so that what holds or describes a spec does not
// include the kinds' code (docs/architecture.md, "What a new kind
// rebuilds").
template <class P>
struct KindOfParams {  // a kind as its parameters know it: what the readers need
  using Params = P;
  static constexpr std::string_view name = P::name;
};

template <class... P>
struct SpecRegistry {
  using Spec = std::variant<P...>;
  static constexpr std::array<std::string_view, sizeof...(P)> names = {P::name...};
  static std::string_view name(const Spec& s) { return names[s.index()]; }
  // f(static_cast<K*>(nullptr)) for each kind K, in order, as Registry's
  // for_each, where K has only the name and Params (KindOfParams).
  template <class F>
  static void for_each(F&& f) {
    (f(static_cast<KindOfParams<P>*>(nullptr)), ...);
  }
  static std::string key(const Spec& s) { return spec_key(names, s); }
  static std::string json(const Spec& s, bool polar = false) { return spec_json(names, s, polar); }
};

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

  // "name field=value ...", exactly: what frames are compared by
  // (spec_key above).
  static std::string key(const Spec& s) { return spec_key(names, s); }

  // {"kind": "name", <each field>: value} (spec_json above).
  static std::string json(const Spec& s, bool polar = false) { return spec_json(names, s, polar); }

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
