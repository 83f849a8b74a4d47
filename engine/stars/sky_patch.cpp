#include "stars/sky_patch.hpp"

#include <algorithm>
#include <cstddef>

namespace lc {

std::optional<SkyPatch> make_patch(const GridNode& a, const GridNode& b, const GridNode& c, const GridNode& d,
                                   double cos_max) {
  if (!a.known || !b.known || !c.known || !d.known) return std::nullopt;
  SkyPatch q{SkyQuad{{a.sky, b.sky, c.sky, d.sky}}, {}, 1.0, {a, b, c, d}};
  Vec3 sum{0, 0, 0};
  for (const Vec3& k : q.sky.c)
    for (int m = 0; m < 3; ++m) sum[m] += k[m];
  q.centre = unit3(sum);
  for (const Vec3& k : q.sky.c) q.cos_reach = std::min(q.cos_reach, dot3(k, q.centre));
  if (q.cos_reach < cos_max) return std::nullopt;
  // Edge k runs from corner k to k + 1; its plane's normal points to the
  // side of the centre, and every other corner must lie on that side.
  q.convex = true;
  for (int k = 0; k < 4; ++k) {
    Vec3 n = cross3(q.sky.c[static_cast<std::size_t>(k)], q.sky.c[static_cast<std::size_t>((k + 1) % 4)]);
    if (dot3(n, q.centre) < 0.0)
      for (double& x : n) x = -x;
    for (int m = 2; m <= 3; ++m)
      if (dot3(n, q.sky.c[static_cast<std::size_t>((k + m) % 4)]) < 0.0) q.convex = false;
    q.inward[static_cast<std::size_t>(k)] = n;
  }
  return q;
}

}  // namespace lc
