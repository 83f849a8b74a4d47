#pragma once
// Reads a struct with declared fields (core/fields.hpp) from a Lua table:
// each field by its type, its default where it has one, its range checked,
// every error naming the field ("disk: field 'rings' must be at least 1,
// got 0").  Before any value is read the table's keys are checked: an
// unknown field (most likely a misspelt one, or one of another kind:
// lc.camera{fov = 180, projection = "fisheye"}) is reported first, with
// the nearest declared name, since a value's error would hide it.  Known
// are the declared fields (all the keys of a KeyedByValue one: a
// placement's `position` and `worldline`), the names in S::extra_fields
// (what a kind reads by hand besides them) and the keys the caller marked
// known before (TableReader::mark_known).  The reader does not finish() the
// table: the caller may read more fields by hand first, and finishes it
// after.

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <type_traits>

#include <fmt/format.h>

#include "core/color.hpp"
#include "core/fields.hpp"
#include "lua/table_reader.hpp"
#include "spacetime/hole_list.hpp"
#include "spacetime/spacetime_spec.hpp"
#include "worldline/placement.hpp"

namespace lc {

// colors = {{r, g, b}, {r, g, b}}: two linear RGB colours, components >= 0.
inline Palette read_palette(lua::TableReader& list) {
  if (list.length() != 2)
    throw lua::FieldError(fmt::format("{}: must hold two colours {{{{r, g, b}}, {{r, g, b}}}}", list.context()));
  Palette out;
  for (std::size_t i = 1; i <= 2; ++i) {
    auto c = list.table_at(i);
    if (c.length() != 3)
      throw lua::FieldError(fmt::format("{}: a colour is {{r, g, b}} (three numbers, linear RGB)", c.context()));
    Color& colour = i == 1 ? out.a : out.b;
    for (std::size_t k = 1; k <= 3; ++k) {
      const double v = c.number_at(k);
      if (v < 0.0) throw lua::FieldError(fmt::format("{}: colour components must be >= 0, got {}", c.context(), v));
      colour[k - 1] = static_cast<float>(v);
    }
    c.finish();
  }
  list.finish();
  return out;
}

// holes = {{mass = m, position = {x = .., y = .., z = ..}}, ...}: one to
// HoleList::capacity holes (spacetime/hole_list.hpp); the spacetime checks
// the values.
inline HoleList read_hole_list(lua::TableReader& list) {
  const std::size_t n = list.length();
  if (n == 0)
    throw lua::FieldError(fmt::format(
        "{}: must list at least one hole {{{{mass = m, position = {{x = .., y = .., z = ..}}}}, ...}}", list.context()));
  if (n > HoleList::capacity)
    throw lua::FieldError(fmt::format("{}: at most {} holes, got {}", list.context(), HoleList::capacity, n));
  HoleList out;
  for (std::size_t i = 1; i <= n; ++i) {
    auto h = list.table_at(i);
    PointHole hole;
    hole.mass = h.number("mass");
    auto at = h.table("position");
    hole.position = {at.number("x"), at.number("y"), at.number("z")};
    at.finish();
    h.finish();
    out.add(hole);
  }
  list.finish();
  return out;
}

// A placement (worldline/placement.hpp): exactly one of `position = {...}`
// (resolved against st, the scene's spacetime, when given: nullptr keeps it
// as written) or `worldline = lc.worldline{...}`.  In scene_reader.cpp,
// beside the readers of positions and worldlines.
Placement read_placement(lua::TableReader& t, const Spacetime* st);

// The declared fields of `out` from the table t; st: the scene's
// spacetime, which positions resolve against (nullptr where there is none
// yet: a constructor's table checked on its own).
template <HasFields S>
void read_fields(lua::TableReader& t, S& out, const Spacetime* st = nullptr) {
  for_each_field<S>([&](const auto& f) {
    using T = typename std::decay_t<decltype(f)>::Value;
    if constexpr (KeyedByValue<T>)
      for (const std::string_view name : T::field_names) t.mark_known({name});
    else
      t.mark_known({f.name});
  });
  if constexpr (requires { S::extra_fields; })
    for (const std::string_view name : S::extra_fields) t.mark_known({name});
  t.finish();
  for_each_field<S>([&](const auto& f) {
    using T = typename std::decay_t<decltype(f)>::Value;
    T v;
    if constexpr (std::is_same_v<T, Placement>) {
      v = read_placement(t, st);
    } else if constexpr (std::is_same_v<T, std::string>) {
      v = f.fallback ? t.string_or(f.name, *f.fallback) : t.string(f.name);
      if (v.empty()) throw lua::FieldError(fmt::format("{}: field '{}' must not be empty", t.context(), f.name));
    } else if constexpr (std::is_same_v<T, Palette>) {
      auto list = t.optional_table(f.name);
      if (list)
        v = read_palette(*list);
      else if (f.fallback)
        v = *f.fallback;
      else
        throw lua::FieldError(fmt::format("{}: missing field '{}'", t.context(), f.name));
    } else if constexpr (std::is_same_v<T, HoleList>) {
      auto list = t.table(f.name);
      v = read_hole_list(list);
    } else if constexpr (Choice<T>) {
      const std::string name = f.fallback ? t.string_or(f.name, std::string(choice_name(*f.fallback))) : t.string(f.name);
      const auto names = choice_names(T{});
      const auto it = std::find(names.begin(), names.end(), name);
      if (it == names.end())
        throw lua::FieldError(fmt::format("{}: field '{}' must be {}, got '{}'", t.context(), f.name,
                                          choices_text<T>(), name));
      v = static_cast<T>(it - names.begin());
    } else if constexpr (std::is_floating_point_v<T>) {
      v = f.fallback ? t.number_or(f.name, *f.fallback) : t.number(f.name);
    } else {
      static_assert(std::is_integral_v<T>,
                    "read_fields reads numbers, strings, palettes, hole lists, choices and placements: teach it a new field type");
      const std::int64_t i = f.fallback ? t.integer_or(f.name, static_cast<std::int64_t>(*f.fallback)) : t.integer(f.name);
      if (!in_range(static_cast<double>(i), f.lo, f.hi))
        throw lua::FieldError(fmt::format("{}: field '{}' must be {}{}{}, got {}", t.context(), f.name, integer_range_text(f.lo, f.hi),
                                          f.unit.empty() ? "" : " ", f.unit, i));
      v = static_cast<T>(i);
    }
    if constexpr (std::is_floating_point_v<T>)
      if (!in_range(v, f.lo, f.hi))
        throw lua::FieldError(fmt::format("{}: field '{}' must be {}{}{}, got {:g}", t.context(), f.name,
                                          range_text(f.lo, f.hi), f.unit.empty() ? "" : " ", f.unit, v));
    out.*(f.member) = v;
  });
}

}  // namespace lc
