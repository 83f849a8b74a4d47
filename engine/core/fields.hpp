#pragma once
// Fields declared once.  A plain struct that a shot script fills lists its
// fields as a `static constexpr auto fields = std::tuple{...}` of Field
// descriptors — name, member, default, range, one line of documentation —
// and from that one list come the Lua reader (script/field_reader.hpp), the
// text and JSON a scene is described in, the exact key frames are compared
// by (scene/still_key.hpp), and the tables of docs/shots.md (`lightcone
// fields`).  Gyoto's GYOTO_PROPERTY_* lines are the model.

#include <cmath>
#include <concepts>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>

#include <fmt/format.h>

#include "core/color.hpp"

namespace lc {

// A closed or open end of a numeric range.
struct Bound {
  double value;
  bool inclusive;
};
inline constexpr Bound at_least(double v) { return {v, true}; }
inline constexpr Bound above(double v) { return {v, false}; }
inline constexpr Bound at_most(double v) { return {v, true}; }
inline constexpr Bound below(double v) { return {v, false}; }

// A field that takes one of a few named values: a scoped enum E for which
// choice_names(E{}) (found by argument-dependent lookup) gives the names in
// the enumerators' order, 0, 1, ...: the shot writes the name.
template <class E>
concept Choice = std::is_enum_v<E> && requires { choice_names(E{}); };

template <Choice E>
constexpr std::string_view choice_name(E e) {
  return choice_names(e)[static_cast<std::size_t>(e)];
}
// "a, b or c".
template <Choice E>
std::string choices_text() {
  const auto names = choice_names(E{});
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += fmt::format("{}{}", i == 0 ? "" : i + 1 == names.size() ? " or " : ", ", names[i]);
  return out;
}

// A field type whose value a shot gives under one of several keys, and
// which says under which (a placement: `position` or `worldline`,
// worldline/placement.hpp).  T::field_names lists them all (the reader's
// check of unknown keys, the reference); v.field_name() is the one v is
// keyed and written under.  The type gives its own text: field_text(v,
// exact) for the key and, holding a position, field_json(v, polar) for
// JSON (polar: whether the scene's positions are {r, theta, phi}).
template <class T>
concept KeyedByValue = requires(const T& v) {
  T::field_names;
  { v.field_name() } -> std::convertible_to<std::string_view>;
};

// The default of a field that cannot have one: the shot gives one of its
// keys (a KeyedByValue type, whose values need not be constants).
struct NoDefault {};

// One field of Owner, of type T (double, int, std::uint32_t, a string, a
// Palette of two colours, a Choice or a KeyedByValue type).  fallback: the
// default, nullopt when the field is required (a string's default is a
// string_view: a std::string cannot live in a constant).  lo, hi: the
// allowed range (for numbers).
template <class T>
struct FieldDefault {
  using type = T;
};
template <>
struct FieldDefault<std::string> {
  using type = std::string_view;
};
template <KeyedByValue T>
struct FieldDefault<T> {
  using type = NoDefault;
};
template <class T>
using FieldDefaultOf = typename FieldDefault<T>::type;

template <class Owner, class T>
struct Field {
  using Value = T;
  std::string_view name;
  T Owner::*member;
  std::optional<FieldDefaultOf<T>> fallback;
  std::optional<Bound> lo = std::nullopt, hi = std::nullopt;
  std::string_view doc = {};
  std::string_view unit = {};  // "degrees", "M", ...: for messages and the docs
  // Left out of a kind's text, JSON and key while it holds its default
  // (quiet_at_default below).
  bool quiet = false;
};

template <class Owner, class T>
constexpr Field<Owner, T> field(std::string_view name, T Owner::*member, std::optional<FieldDefaultOf<T>> fallback,
                                std::optional<Bound> lo, std::optional<Bound> hi, std::string_view doc,
                                std::string_view unit = {}) {
  return {name, member, fallback, lo, hi, doc, unit};
}

// A field added to a kind after frames were made with it (a Kerr hole's
// charge): the text, JSON and key of a value leave it out while it holds
// its default, so the kind's earlier scenes are described (and their frame
// files written) byte for byte as before, and only a value that uses the
// field names it.
template <class Owner, class T>
constexpr Field<Owner, T> quiet_at_default(Field<Owner, T> f) {
  f.quiet = true;
  return f;
}

// Whether the field f of a value holding v is left out of its text.
template <class F>
bool left_out(const F& f, const typename F::Value& v) {
  if constexpr (std::equality_comparable_with<typename F::Value, FieldDefaultOf<typename F::Value>>)
    return f.quiet && f.fallback && v == *f.fallback;
  else
    return false;
}

// Whether a struct declares its fields.
template <class S>
concept HasFields = requires { S::fields; };

// f(field) for every field of S, in declaration order.
template <HasFields S, class F>
constexpr void for_each_field(F&& f) {
  std::apply([&](const auto&... fd) { (f(fd), ...); }, S::fields);
}

// "must be between 0 and 180 (exclusive)" style text for a range, or "".
inline std::string range_text(const std::optional<Bound>& lo, const std::optional<Bound>& hi) {
  auto num = [](double v) { return fmt::format("{:.12g}", v); };
  if (lo && hi) {
    if (lo->inclusive && hi->inclusive) return fmt::format("between {} and {}", num(lo->value), num(hi->value));
    if (!lo->inclusive && !hi->inclusive)
      return fmt::format("greater than {} and less than {}", num(lo->value), num(hi->value));
    return fmt::format("{} {} and {} {}", lo->inclusive ? "at least" : "greater than", num(lo->value),
                       hi->inclusive ? "at most" : "less than", num(hi->value));
  }
  if (lo) return fmt::format("{} {}", lo->inclusive ? "at least" : "greater than", num(lo->value));
  if (hi) return fmt::format("{} {}", hi->inclusive ? "at most" : "less than", num(hi->value));
  return {};
}

// The same for a whole-number field: "0 or 1" where it has two values.
inline std::string integer_range_text(const std::optional<Bound>& lo, const std::optional<Bound>& hi) {
  if (lo && hi && lo->inclusive && hi->inclusive && hi->value == lo->value + 1)
    return fmt::format("{:.12g} or {:.12g}", lo->value, hi->value);
  return range_text(lo, hi);
}

// Whether v lies in the range (NaN never does).
inline bool in_range(double v, const std::optional<Bound>& lo, const std::optional<Bound>& hi) {
  if (std::isnan(v)) return false;
  if (lo && (lo->inclusive ? v < lo->value : v <= lo->value)) return false;
  if (hi && (hi->inclusive ? v > hi->value : v >= hi->value)) return false;
  return true;
}

// A field's value as text: exact (hex floats, for keys that must tell every
// value apart) or for people and JSON (12 significant digits; JSON has no
// NaN or infinity: null).
inline std::string field_text(double v, bool exact) {
  if (exact) return fmt::format("{:a}", v);
  if (!std::isfinite(v)) return "null";
  return fmt::format("{:.12g}", v);
}
template <class T>
  requires std::is_integral_v<T>
std::string field_text(T v, bool) {
  return fmt::format("{}", v);
}

inline std::string field_text(const std::string& v, bool) {
  std::string out = "\"";
  for (const char c : v) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", c);
      continue;
    }
    out += c;
  }
  return out + "\"";
}
template <Choice E>
std::string field_text(E e, bool exact) {
  return exact ? std::string(choice_name(e)) : field_text(std::string(choice_name(e)), false);
}
inline std::string field_text(const Palette& p, bool exact) {
  auto colour = [exact](const Color& c) {
    return exact ? fmt::format("{:a},{:a},{:a}", c[0], c[1], c[2])
                 : fmt::format("[{}, {}, {}]", field_text(double{c[0]}, false), field_text(double{c[1]}, false),
                               field_text(double{c[2]}, false));
  };
  return exact ? fmt::format("{};{}", colour(p.a), colour(p.b)) : fmt::format("[{}, {}]", colour(p.a), colour(p.b));
}

// The key a field's value v is given under: its declared name, or the one
// a KeyedByValue value says.
template <class F>
std::string_view field_key_name(const F& f, const typename F::Value& v) {
  if constexpr (KeyedByValue<typename F::Value>)
    return v.field_name();
  else
    return f.name;
}

// A value as JSON; polar: whether the scene's positions are polar, for a
// type holding one (which says so with field_json).
template <class T>
std::string field_json_text(const T& v, bool polar) {
  if constexpr (requires { field_json(v, polar); })
    return field_json(v, polar);
  else
    return field_text(v, false);
}

// " name=value" for every field of s, exactly: what frames are compared by.
template <HasFields S>
std::string fields_key(const S& s) {
  std::string out;
  for_each_field<S>([&](const auto& f) {
    const auto& v = s.*(f.member);
    if (left_out(f, v)) return;
    out += fmt::format(" {}={}", field_key_name(f, v), field_text(v, true));
  });
  return out;
}

// ", \"name\": value" for every field of s, as JSON members (polar: whether
// the scene's positions are polar).
template <HasFields S>
std::string fields_json(const S& s, bool polar = false) {
  std::string out;
  for_each_field<S>([&](const auto& f) {
    const auto& v = s.*(f.member);
    if (left_out(f, v)) return;
    out += fmt::format(", \"{}\": {}", field_key_name(f, v), field_json_text(v, polar));
  });
  return out;
}

}  // namespace lc
