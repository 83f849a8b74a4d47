#pragma once
// Colours: linear RGB as floats, and the pair of colours a checker
// alternates (a shot's `colors = {{r, g, b}, {r, g, b}}`).

#include <array>

namespace lc {

using Color = std::array<float, 3>;

struct Palette {
  Color a, b;
  bool operator==(const Palette&) const = default;
};

// The colour of checker cell (i, j).
inline Color checker(long i, long j, const Palette& p) { return ((i + j) & 1) == 0 ? p.a : p.b; }

}  // namespace lc
