#include "geodesic_csv.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/constants.hpp"

namespace lc {

std::string geodesic_csv_header(bool with_tetrad, bool bundle) {
  std::string out = bundle ? "ray,lambda,x0,x1,x2,x3,u0,u1,u2,u3" : "lambda,x0,x1,x2,x3,u0,u1,u2,u3";
  if (with_tetrad)
    for (int a = 0; a < 4; ++a)
      for (int m = 0; m < 4; ++m) out += fmt::format(",e{}{}", a, m);
  out += '\n';
  return out;
}

void append_geodesic_csv(std::string& out, const Spacetime& spacetime, const GeodesicPath& path, bool with_tetrad,
                         std::optional<int> ray) {
  std::visit(
      [&](const auto& st) {
        double phi_prev = 0.0, phi_offset = 0.0;
        bool first = true;
        for (const auto& s : path.samples) {
          Vec4 x = st.scene_from_trace(s.x);
          if (has_polar_scene(spacetime)) {
            // Unwrap phi: choose the 2 pi branch nearest the previous sample.
            if (!first) phi_offset += two_pi * std::round((phi_prev - (x[3] + phi_offset)) / two_pi);
            phi_prev = x[3] + phi_offset;
            x[3] = phi_prev;
            first = false;
          }
          const Vec4 u = st.scene_vector(s.x, s.u);
          if (ray) out += fmt::format("{},", *ray);
          // %.17g: round-trips doubles exactly.
          out += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", s.lambda, x[0],
                             x[1], x[2], x[3], u[0], u[1], u[2], u[3]);
          if (with_tetrad)
            for (int a = 0; a < 4; ++a) {
              const Vec4 e = st.scene_vector(s.x, s.e[a]);
              for (int m = 0; m < 4; ++m) out += fmt::format(",{:.17g}", e[m]);
            }
          out += '\n';
        }
      },
      spacetime);
}

}  // namespace lc
