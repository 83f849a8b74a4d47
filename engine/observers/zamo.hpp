#pragma once
// lc.zamo{r, theta, phi} / {x, y, z}: the zero-angular-momentum observer at
// a place (4-velocity along -grad t, eye/tetrad.hpp): it exists
// everywhere outside the horizon, the ergoregion included; in a static
// spacetime it is the static observer.

#include <string_view>

#include "eye/tetrad.hpp"
#include "observers/at_rest.hpp"

namespace lc {

class Zamo : public AtRestObserver<Zamo> {
 public:
  static constexpr std::string_view name = "zamo";  // lc.zamo{...}
  static constexpr std::string_view title = "ZAMO";  // in messages
  using AtRestObserver::AtRestObserver;

  // Its frame at a scene point: throws ObserverError inside a horizon.
  template <class S>
  static Tetrad tetrad(const S& st, const Vec4& scene_point) {
    return zamo_polar_tetrad(st, scene_point);
  }
};

}  // namespace lc
