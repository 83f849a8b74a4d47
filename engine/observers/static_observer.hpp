#pragma once
// lc.static_observer{r, theta, phi} / {x, y, z}: at rest at a place (its
// 4-velocity along the scene time's ∂t), legs along the polar basis there
// (eye/tetrad.hpp).  None exists inside a Kerr ergoregion.

#include <string_view>

#include "eye/tetrad.hpp"
#include "observers/at_rest.hpp"

namespace lc {

class StaticObserver : public AtRestObserver<StaticObserver> {
 public:
  static constexpr std::string_view name = "static_observer";  // lc.static_observer{...}
  static constexpr std::string_view title = "static observer";  // in messages
  using AtRestObserver::AtRestObserver;

  // Its frame at a scene point: throws ObserverError inside a horizon or
  // the ergoregion.
  template <class S>
  static Tetrad tetrad(const S& st, const Vec4& scene_point) {
    return static_polar_tetrad(st, scene_point);
  }
};

}  // namespace lc
