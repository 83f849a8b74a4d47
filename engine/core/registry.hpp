#pragma once
// A registry of kinds of one concept (cameras, skies, objects): the kinds,
// one line each, as Registry<K...>.  Each kind K is a class with a static
// `name` (its Lua constructor lc.<name>{...}) and a `Params` struct with
// declared fields (core/fields.hpp).  From that list come the variant of
// parameters a scene holds (Spec), the variant of built kinds (Kinds), the
// names, the exact key and the JSON of a spec, and building a kind from its
// spec: nothing else lists the kinds.

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

  // "name field=value ...", exactly: what frames are compared by.
  static std::string key(const Spec& s) {
    return std::string(name(s)) + std::visit([](const auto& p) { return fields_key(p); }, s);
  }

  // {"kind": "name", <each field>: value}.
  static std::string json(const Spec& s) {
    return fmt::format("{{\"kind\": \"{}\"{}}}", name(s), std::visit([](const auto& p) { return fields_json(p); }, s));
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

}  // namespace lc
