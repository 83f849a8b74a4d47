#pragma once
// Where a body is: held at rest at a position, or falling freely along a
// worldline.  A declared field type (core/fields.hpp, KeyedByValue): a
// kind's Params declare `field("placement", &Params::placement, ...)` and
// from that one line the shot's `position = {...}` or `worldline = w` is
// read (script/field_reader.hpp), keyed exactly (the still key: two frames
// with the body elsewhere never share rays), written as JSON and listed in
// the reference, with no member of the kind's own to forget.

#include <array>
#include <string>
#include <string_view>
#include <variant>

#include <fmt/format.h>

#include "core/json.hpp"
#include "core/tensor.hpp"
#include "worldline/worldline_spec.hpp"

namespace lc {

struct Placement {
  // A rest position (scene coordinates; its time is not part of where a
  // body at rest is) or the worldline it falls along.
  std::variant<Vec4, WorldlineSpec> at{};

  // The shot's keys, in the order of the variant's alternatives.
  static constexpr std::array<std::string_view, 2> field_names = {"position", "worldline"};
  std::string_view field_name() const { return field_names[at.index()]; }

  // The rest position, or nullptr for a worldline; and the other way round.
  const Vec4* rest() const { return std::get_if<Vec4>(&at); }
  const WorldlineSpec* worldline() const { return std::get_if<WorldlineSpec>(&at); }
};

// Exactly (the still key): a rest position's x1..x3 (its time is left out,
// as for a static observer), or the worldline's key.  For people: the same
// as the JSON in a Cartesian scene.
inline std::string field_text(const Placement& p, bool exact) {
  if (const Vec4* x = p.rest())
    return exact ? fmt::format("{:a},{:a},{:a}", (*x)[1], (*x)[2], (*x)[3]) : json_position(*x, false);
  return exact ? p.worldline()->key() : p.worldline()->json();
}

// As JSON: a position in the scene's chart (polar: {t, r, theta, phi} in
// degrees), or the worldline's own JSON.
inline std::string field_json(const Placement& p, bool polar) {
  if (const Vec4* x = p.rest()) return json_position(*x, polar);
  return p.worldline()->json();
}

}  // namespace lc
