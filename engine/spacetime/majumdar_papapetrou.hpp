#pragma once
// Majumdar–Papapetrou spacetime with any number of extreme
// Reissner–Nordström holes at rest anywhere (spacetime/extreme_holes.hpp):
// U = 1 + Σ m_i / |x - x_i| in isotropic Cartesian coordinates.  Each hole's
// charge equals its mass, so gravity and electric repulsion balance between
// every pair and the holes stay where they are put: the configuration is
// static whatever the positions.  The dihole is the case of two holes on
// the z axis (spacetime/dihole.hpp keeps the paper's own algebra).

#include <algorithm>
#include <cmath>
#include <string>

#include "core/constants.hpp"
#include "core/lanes.hpp"
#include "spacetime/cartesian_scene.hpp"
#include "spacetime/extreme_holes.hpp"
#include "spacetime/hole_list.hpp"
#include "spacetime/model.hpp"

namespace lc {

// No thin-disk flux is worked out for these holes (objects/disk_physics.hpp),
// and their equatorial matter is at rest (spacetime/equatorial_flow.hpp):
// the plane z = 0 is no plane of symmetry for holes anywhere.
class MajumdarPapapetrou : public CartesianScene,
                           public ExtremeHoles<MajumdarPapapetrou>,
                           public HamiltonianFromRhs<MajumdarPapapetrou>,
                           public CartesianInfinity,
                           public ObserversOutsideHorizons<MajumdarPapapetrou> {
 public:
  static constexpr std::string_view name = "majumdar_papapetrou";
  static constexpr SceneChart chart = SceneChart::cartesian;
  static constexpr bool stationary = true;  // static holes; see Kerr::stationary
  // Infinity, and the holes' horizons as one end (the capture rule does not
  // tell them apart).
  static constexpr std::array ends = {SpacetimeEnd{"infinity", EndKind::infinity},
                                      SpacetimeEnd{"horizon", EndKind::horizon}};
  struct Params {
    HoleList holes;
    static constexpr auto fields = std::tuple{
        field("holes", &Params::holes, std::optional<HoleList>{}, std::nullopt, std::nullopt,
              "the holes, 1 to 16: `{{mass = m, position = {x = .., y = .., z = ..}}, ...}`, each an extreme "
              "Reissner–Nordström hole (charge = mass > 0) at rest at its isotropic Cartesian position"),
    };
  };
  // Throws std::invalid_argument for no holes, a mass <= 0 or not finite, a
  // position not finite, and holes closer than their capture spheres.
  explicit MajumdarPapapetrou(const Params& p);
  Params params() const { return {holes_}; }
  MajumdarPapapetrou for_tracing(TimeDirection) const { return *this; }
  static std::vector<SpacetimeExample<MajumdarPapapetrou>> examples();

  const HoleList& holes() const { return holes_; }
  double asymptotic_mass() const { return mass_; }
  // Photon orbits lie within 4 Σ m_i of the holes, which lie within
  // `extent_` of the origin.
  double photon_reach() const { return 4.0 * mass_ + extent_; }
  // Where the multipoles beyond the monopole bend light by less than
  // far_field_bending: the dipole |Σ m_i x_i| / r^2 and (bounding the
  // quadrupole and beyond) Σ m_i |x_i|^2 / r^3, as for the dihole
  // (Dihole::far_field_radius, the same figures for two holes on the axis).
  double far_field_radius() const { return far_field_radius_; }

  // U and its gradient at the spatial point (X, Y, Z), T double or lanes
  // (spacetime/extreme_holes.hpp): one term per hole.
  template <class T>
  [[gnu::always_inline]] T potential_with_gradient(const T& X, const T& Y, const T& Z, T& gx, T& gy, T& gz) const {
    T U = T{} + 1.0;
    gx = gy = gz = T{};
    for (const PointHole& h : holes_) {
      const T dx = X - h.position[0], dy = Y - h.position[1], dz = Z - h.position[2];
      const T inv = 1.0 / sqrt_of(dx * dx + dy * dy + dz * dz);
      U += h.mass * inv;
      const T c = h.mass * inv * inv * inv;
      gx -= c * dx;
      gy -= c * dy;
      gz -= c * dz;
    }
    return U;
  }

 private:
  HoleList holes_;
  double mass_ = 0.0, extent_ = 0.0, far_field_radius_ = 0.0;
};

}  // namespace lc
