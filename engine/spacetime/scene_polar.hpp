#pragma once
// Scene time, radius and longitude of an event, for data layers and reports.

#include <cmath>
#include <type_traits>

#include "core/constants.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

// Scene time, radius and longitude of a trace-coordinate event: Boyer–Lindquist
// for Kerr, spherical about the origin otherwise.
template <class S>
inline void scene_polar(const S& st, const Vec4& x, double& t, double& r, double& phi) {
  if constexpr (std::is_same_v<S, Kerr>) {
    const Vec4 s = st.scene_from_trace(x);
    t = s[0];
    r = s[1];
    phi = s[3];
  } else {
    t = x[0];
    r = std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    phi = std::atan2(x[2], x[1]);
    if (phi < 0) phi += two_pi;
  }
}

}  // namespace lc
