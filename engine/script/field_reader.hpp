#pragma once
// Reads a struct with declared fields (core/fields.hpp) from a Lua table:
// each field by its type, its default where it has one, its range checked,
// every error naming the field ("disk: field 'rings' must be at least 1,
// got 0").  The reader does not finish() the table: the caller may read
// more fields by hand first.

#include <cstdint>
#include <type_traits>

#include <fmt/format.h>

#include "core/fields.hpp"
#include "lua/table_reader.hpp"

namespace lc {

template <HasFields S>
void read_fields(lua::TableReader& t, S& out) {
  for_each_field<S>([&](const auto& f) {
    using T = typename std::decay_t<decltype(f)>::Value;
    T v;
    if constexpr (std::is_floating_point_v<T>) {
      v = f.fallback ? t.number_or(f.name, *f.fallback) : t.number(f.name);
    } else {
      static_assert(std::is_integral_v<T>, "read_fields reads numbers; read other fields by hand");
      const std::int64_t i = f.fallback ? t.integer_or(f.name, static_cast<std::int64_t>(*f.fallback)) : t.integer(f.name);
      if (!in_range(static_cast<double>(i), f.lo, f.hi))
        throw lua::FieldError(fmt::format("{}: field '{}' must be {}{}, got {}", t.context(), f.name, range_text(f.lo, f.hi),
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
