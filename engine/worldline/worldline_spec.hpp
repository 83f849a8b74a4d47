#pragma once
// What a shot says of a free-falling body: plain data, integrated into a
// Worldline (worldline/worldline.hpp) once per shot.

#include <string>

#include <fmt/format.h>

#include "core/json.hpp"
#include "core/tensor.hpp"
#include "spacetime/spacetime_spec.hpp"

namespace lc {

// A free-falling worldline: a timelike geodesic from `start` (scene
// coordinates) with 3-velocity `velocity` relative to the static observer
// there (components on e_r, e_theta, e_phi or e_x, e_y, e_z; units of c),
// integrated for `duration` of proper time.  Identical specs within a shot
// share one integration.
struct WorldlineSpec {
  Spacetime spacetime;  // Minkowski unless set
  Vec4 start{};
  Vec3 velocity{};
  double duration = 0.0;
  std::string where;  // "shot.lua:12", where the script made it

  // Exact textual key of the parameters, for sharing integrations.
  std::string key() const;
  // As JSON (`lightcone inspect`).
  std::string json() const {
    const bool polar = has_polar_scene(spacetime);
    return fmt::format("{{\"spacetime\": {}, \"start\": {}, \"velocity\": [{}, {}, {}], \"duration\": {}, \"where\": {}}}",
                       spacetime_json(spacetime), json_position(start, polar), json_number(velocity[0]),
                       json_number(velocity[1]), json_number(velocity[2]), json_number(duration), json_string(where));
  }
};

}  // namespace lc
