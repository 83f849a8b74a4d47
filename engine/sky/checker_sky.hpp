#pragma once
// lc.sky_checker{...}: a procedural checker at infinity, rows in the
// colatitude from +z, columns in the longitude atan2(y, x), its colours'
// light times 2^brightness as the other skies'.

#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "core/color.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "sky/point_star_sky.hpp"
#include "sky/texture_sky.hpp"

namespace lc {

class ShotResources;

class CheckerSky {
 public:
  static constexpr std::string_view name = "sky_checker";
  struct Params {
    int rows = 18, columns = 36;
    Palette colors = {{0.6f, 0.6f, 0.65f}, {0.05f, 0.05f, 0.08f}};
    double rotate = 0.0, brightness = 0.0;
    static constexpr auto fields = std::tuple{
        field("rows", &Params::rows, std::optional<int>{18}, at_least(1), at_most(100000), "cells in colatitude"),
        field("columns", &Params::columns, std::optional<int>{36}, at_least(1), at_most(100000), "cells in longitude"),
        field("colors", &Params::colors, std::optional<Palette>{Palette{{0.6f, 0.6f, 0.65f}, {0.05f, 0.05f, 0.08f}}},
              std::nullopt, std::nullopt, "the two colours {{r, g, b}, {r, g, b}}, linear RGB"),
        field("rotate", &Params::rotate, std::optional<double>{0.0}, std::nullopt, std::nullopt,
              "added to the longitude", "degrees"),
        field("brightness", &Params::brightness, std::optional<double>{0.0}, at_least(-64.0), at_most(64.0),
              "the colours' light times 2^brightness (for scenes in physical units: docs/light.md)", "stops"),
    };
  };
  static std::vector<std::string> assets(const Params&) { return {}; }
  // What render --sky kstars delivers it as: a stand-in for a sky, it gives
  // way to the real stars at its rotation and brightness.
  static PointStarSky::Params real_stars(const Params& p) { return real_stars_at(p.rotate, p.brightness); }

  CheckerSky(const Params& p, ShotResources&) : p_(p), scale_(brightness_scale(p.brightness)) {}

  // Colour in the direction (theta from +z, phi = atan2(y, x)).
  Color color(double theta, double phi) const {
    phi = rotated_longitude(phi, p_.rotate);
    const long row = static_cast<long>(std::floor(theta / pi * p_.rows));
    const long col = static_cast<long>(std::floor(phi / two_pi * p_.columns));
    return scaled(checker(row, col, p_.colors), scale_);
  }

 private:
  Params p_;
  float scale_;
};

}  // namespace lc
