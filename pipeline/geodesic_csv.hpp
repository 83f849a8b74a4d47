#pragma once
// CSV of sampled geodesics in scene coordinates: Boyer–Lindquist
// (t, r, theta, phi) for Kerr, Cartesian (t, x, y, z) otherwise; angles in
// radians, phi unwrapped (continuous) so that orbits plot without jumps.
// Columns: [ray,]lambda,x0..x3,u0..u3[,e00..e33] (e<leg><component>); the
// ray column (1-based) only for bundles.

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "geodesic/geodesic_solver.hpp"

namespace lc {

std::string geodesic_csv_header(bool with_tetrad, bool bundle);

// Appends one row per sample; `ray` is written as the first column when set.
void append_geodesic_csv(std::string& out, const Spacetime& st, const GeodesicPath& path, bool with_tetrad,
                         std::optional<int> ray);

// A curve read back from such a CSV: its events x0..x3, in file order.
struct CsvCurve {
  int ray = 1;  // the ray column's value (1 without one)
  std::vector<std::array<double, 4>> events;
  std::vector<long> lines;  // each event's line in the file (1-based), for messages
};

// The longest CSV line read: a row with the tetrad is 26 numbers of ~24
// characters.  A longer line is refused without being held whole.
inline constexpr std::size_t max_csv_line = 16 * 1024;

// Reads a CSV written by `lightcone geodesic`: one curve per run of rows
// with the same ray (the whole file without a ray column).  Throws
// std::invalid_argument naming the file, and the line where a row is at
// fault (a line longer than max_csv_line, a missing column, a number that
// is not one or not finite, a ray
// that is not a whole number from 1, a row of another length), or the file
// when it cannot be read or holds no rows.
std::vector<CsvCurve> read_geodesic_csv(const std::filesystem::path& file);

}  // namespace lc
