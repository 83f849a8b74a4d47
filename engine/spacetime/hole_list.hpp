#pragma once
// A list of point holes, each a mass at a Cartesian position: the value of
// lc.majumdar_papapetrou{holes = {...}}.  A declared field's type
// (core/fields.hpp) of its own: the reader (script/field_reader.hpp), the
// key, the JSON and the reference tables know it.  Held in place (at most
// `capacity` holes) so that the spacetime holding it stays a value the ray
// loop copies without a heap.

#include <array>
#include <cstddef>
#include <string>

#include <fmt/format.h>

#include "core/fields.hpp"
#include "core/tensor.hpp"

namespace lc {

struct PointHole {
  double mass = 0.0;
  Vec3 position{};
  bool operator==(const PointHole&) const = default;
};

struct HoleList {
  // More holes would each cost every step of every ray a square root; 16
  // is four times the largest configuration asked for (a square).
  static constexpr std::size_t capacity = 16;
  std::array<PointHole, capacity> holes{};
  std::size_t count = 0;

  const PointHole* begin() const { return holes.data(); }
  const PointHole* end() const { return holes.data() + count; }
  // Appends h; false when the list is full.
  bool add(const PointHole& h) {
    if (count == capacity) return false;
    holes[count++] = h;
    return true;
  }
  // Unused entries stay zero, so the default comparison compares the holes.
  bool operator==(const HoleList&) const = default;
};

// The holes as a key (exact: hex floats, "m@x,y,z;...") or as JSON
// ([{"mass": m, "position": [x, y, z]}, ...]).
inline std::string field_text(const HoleList& list, bool exact) {
  std::string out = exact ? "{" : "[";
  for (const PointHole& h : list) {
    if (&h != list.begin()) out += exact ? ";" : ", ";
    if (exact)
      out += fmt::format("{:a}@{:a},{:a},{:a}", h.mass, h.position[0], h.position[1], h.position[2]);
    else
      out += fmt::format("{{\"mass\": {}, \"position\": [{}, {}, {}]}}", field_text(h.mass, false),
                         field_text(h.position[0], false), field_text(h.position[1], false),
                         field_text(h.position[2], false));
  }
  return out + (exact ? "}" : "]");
}

// The holes for people (a frame's header, messages): "{0.3 at (1, 0, 0), ...}".
inline std::string people_text(const HoleList& list) {
  std::string out = "{";
  for (const PointHole& h : list)
    out += fmt::format("{}{:g} at ({:g}, {:g}, {:g})", &h == list.begin() ? "" : ", ", h.mass, h.position[0],
                       h.position[1], h.position[2]);
  return out + "}";
}

}  // namespace lc
