#pragma once
// CSV of sampled geodesics in the spacetime's scene coordinates: polar
// (t, r, theta, phi), Boyer–Lindquist for Kerr, or Cartesian (t, x, y, z);
// angles in radians, phi unwrapped (continuous) so that orbits plot without
// jumps.  The first line records the chart, "# chart: bl (t, r, theta, phi;
// kerr)", so that `lightcone plot` need not be told; then the columns
// [ray,]lambda,x0..x3,u0..u3[,e00..e33] (e<leg><component>), the ray column
// (1-based) only for bundles.

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geodesic/geodesic_solver.hpp"

namespace lc {

// The name a scene chart has in a CSV's chart line and in `plot
// --coordinates`: bl for the polar chart (Boyer–Lindquist-like r, theta,
// phi), cartesian.  In the enumerators' order.
inline constexpr std::array<std::string_view, 2> csv_chart_names = {"bl", "cartesian"};
inline std::string_view csv_chart_name(SceneChart c) { return csv_chart_names[static_cast<std::size_t>(c)]; }

// The chart line and the column header, for rays in `spacetimes` (all in
// one scene chart: the caller checks; one name per kind, in order).
std::string geodesic_csv_header(const std::vector<Spacetime>& spacetimes, bool with_tetrad, bool bundle);

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

// What such a CSV holds: its chart (none in a CSV from before the chart
// line, whose reader must say: plot --coordinates) and its curves.
struct GeodesicCsv {
  std::optional<SceneChart> chart;
  std::vector<CsvCurve> curves;
};

// Reads a CSV written by `lightcone geodesic`: lines starting with '#'
// before the header are comments, of which "# chart: NAME ..." names the
// chart; one curve per run of rows with the same ray (the whole file
// without a ray column).  Throws std::invalid_argument naming the file, and
// the line where it is at fault (a line longer than max_csv_line, a chart
// not in csv_chart_names, a missing column, a number that is not one or
// not finite, a ray that is not a whole number from 1, a row of another
// length), or the file when it cannot be read or holds no rows.
GeodesicCsv read_geodesic_csv(const std::filesystem::path& file);

}  // namespace lc
