#pragma once
// CSV of sampled geodesics in scene coordinates: Boyer–Lindquist
// (t, r, theta, phi) for Kerr, Cartesian (t, x, y, z) otherwise; angles in
// radians, phi unwrapped (continuous) so that orbits plot without jumps.
// Columns: [ray,]lambda,x0..x3,u0..u3[,e00..e33] (e<leg><component>); the
// ray column (1-based) only for bundles.

#include <optional>
#include <string>

#include "geodesic/geodesic_solver.hpp"

namespace lc {

std::string geodesic_csv_header(bool with_tetrad, bool bundle);

// Appends one row per sample; `ray` is written as the first column when set.
void append_geodesic_csv(std::string& out, const Spacetime& st, const GeodesicPath& path, bool with_tetrad,
                         std::optional<int> ray);

}  // namespace lc
