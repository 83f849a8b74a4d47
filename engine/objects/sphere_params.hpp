#pragma once
// The parameters of the checkered sphere (objects/sphere.hpp), as a shot
// gives them (lc.sphere{...}): plain data with declared fields, apart from
// the sphere so that what holds or describes an object spec
// (objects/object_spec.hpp) does not include the sphere's code.

#include <optional>
#include <string_view>
#include <tuple>

#include "core/color.hpp"
#include "core/fields.hpp"
#include "worldline/placement.hpp"

namespace lc {

struct SphereParams {
  static constexpr std::string_view name = "sphere";  // lc.sphere{...}
  double radius = 1.0;
  int rows = 8, columns = 16;
  Palette colors = {{0.95f, 0.95f, 0.95f}, {0.8f, 0.1f, 0.1f}};
  // Held at rest at `position` (scene coordinates) or falling along
  // `worldline`: a declared field like the others (worldline/placement.hpp).
  Placement placement;
  static constexpr auto fields = std::tuple{
      field("radius", &SphereParams::radius, std::optional<double>{}, above(0.0), std::nullopt, "proper radius", "M"),
      field("rows", &SphereParams::rows, std::optional<int>{8}, at_least(1), at_most(100000), "checker cells from pole to pole"),
      field("columns", &SphereParams::columns, std::optional<int>{16}, at_least(1), at_most(100000),
            "checker cells round the pole"),
      field("colors", &SphereParams::colors, std::optional<Palette>{Palette{{0.95f, 0.95f, 0.95f}, {0.8f, 0.1f, 0.1f}}},
            std::nullopt, std::nullopt, "the two colours {{r, g, b}, {r, g, b}}, linear RGB"),
      field("placement", &SphereParams::placement, std::optional<NoDefault>{}, std::nullopt, std::nullopt,
            "one of the two: `position = {...}`, held at rest there (see Positions), or `worldline = w`, falling "
            "along the worldline w"),
  };
};

}  // namespace lc
