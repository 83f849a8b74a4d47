#pragma once
// The parameters of the thin disk (objects/disk.hpp), as a shot gives them
// (lc.disk{...}): plain data with declared fields, apart from the disk so
// that what holds or describes an object spec (objects/object_spec.hpp)
// does not include the disk's code.

#include <optional>
#include <stdexcept>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "core/color.hpp"
#include "core/fields.hpp"

namespace lc {

struct DiskParams {
  static constexpr std::string_view name = "disk";  // lc.disk{...}
  double inner = 6.0, outer = 20.0;
  int rings = 7, sectors = 24;
  Palette colors = {{1.0f, 0.55f, 0.15f}, {0.35f, 0.12f, 0.03f}};
  double temperature = 0.0, color_correction = 1.0;
  double solar_masses = 0.0, accretion_rate = 0.0;
  static constexpr auto fields = std::tuple{
      field("inner", &DiskParams::inner, std::optional<double>{}, at_least(0.0), std::nullopt, "inner radius", "M"),
      field("outer", &DiskParams::outer, std::optional<double>{}, std::nullopt, std::nullopt, "outer radius, above inner", "M"),
      field("rings", &DiskParams::rings, std::optional<int>{7}, at_least(1), at_most(100000), "checker cells in r"),
      field("sectors", &DiskParams::sectors, std::optional<int>{24}, at_least(1), at_most(100000),
            "checker cells in phi"),
      field("colors", &DiskParams::colors, std::optional<Palette>{Palette{{1.0f, 0.55f, 0.15f}, {0.35f, 0.12f, 0.03f}}},
            std::nullopt, std::nullopt, "the two colours {{r, g, b}, {r, g, b}}, linear RGB"),
      field("temperature", &DiskParams::temperature, std::optional<double>{0.0}, at_least(0.0), at_most(1e9),
            "0: the checker; above 0: a Novikov–Thorne disk (Kerr only) glowing as a blackbody whose hottest ring "
            "has this temperature, seen as lc.light{...} says (model = \"shifted\": through the frequency shift g; "
            "docs/light.md); that ring, seen unshifted, has luminance 1",
            "K"),
      field("color_correction", &DiskParams::color_correction, std::optional<double>{1.0}, at_least(1.0), at_most(10.0),
            "a glowing disk's colour-correction factor f: each ring shines as a blackbody at f T diluted by "
            "f^-4 (hot disks: ~1.7)"),
      field("solar_masses", &DiskParams::solar_masses, std::optional<double>{0.0}, at_least(0.0), at_most(1e12),
            "with accretion_rate, instead of temperature: the hole's mass in the Sun's, which the spacetime's "
            "mass stands for; the rings' temperatures follow, and the light is in cd/m^2 (docs/light.md)",
            "M_sun"),
      field("accretion_rate", &DiskParams::accretion_rate, std::optional<double>{0.0}, at_least(0.0), at_most(1e6),
            "with solar_masses: the rest mass accreted per year", "M_sun/yr"),
  };
  // Throws std::invalid_argument unless inner < outer and the disk's glow
  // is given one way.
  void validate() const {
    if (!(outer > inner))
      throw std::invalid_argument(fmt::format("inner radius {} must be below the outer radius {}", inner, outer));
    if ((solar_masses > 0.0) != (accretion_rate > 0.0))
      throw std::invalid_argument(fmt::format(
          "a disk's glow from physical units needs both solar_masses and accretion_rate above 0, got {} and {}",
          solar_masses, accretion_rate));
    if (solar_masses > 0.0 && temperature > 0.0)
      throw std::invalid_argument(
          "give a glowing disk either its temperature or its solar_masses and accretion_rate, not both");
  }
  // Whether it glows (else it is the checker).
  bool glows() const { return temperature > 0.0 || solar_masses > 0.0; }
};

}  // namespace lc
