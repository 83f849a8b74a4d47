#include "spacetime/majumdar_papapetrou.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "spacetime/extreme_holes_impl.hpp"

namespace lc {

MajumdarPapapetrou::MajumdarPapapetrou(const Params& p) : holes_(p.holes) {
  if (holes_.count == 0)
    throw std::invalid_argument(
        "majumdar_papapetrou: give at least one hole (flat space without holes is lc.minkowski{})");
  Vec3 dipole{};
  double spread = 0.0;
  for (std::size_t i = 0; i < holes_.count; ++i) {
    const PointHole& h = holes_.holes[i];
    if (!std::isfinite(h.mass) || !(h.mass > 0.0))
      throw std::invalid_argument(fmt::format(
          "majumdar_papapetrou: hole {}'s mass must be a number > 0, got {} (leave a hole out to have none there)",
          i + 1, h.mass));
    if (!std::all_of(h.position.begin(), h.position.end(), [](double v) { return std::isfinite(v); }))
      throw std::invalid_argument(fmt::format("majumdar_papapetrou: hole {}'s position must be finite numbers", i + 1));
    // Two holes closer than this share the capture rule's dark region
    // (U > extreme_hole_capture_potential about each reaches the other):
    // lightcone could not show them apart, and at distance 0 U is singular.
    for (std::size_t j = 0; j < i; ++j) {
      const PointHole& o = holes_.holes[j];
      const double apart = norm3({h.position[0] - o.position[0], h.position[1] - o.position[1],
                                  h.position[2] - o.position[2]});
      const double least = (h.mass + o.mass) / (extreme_hole_capture_potential - 1.0);
      if (!(apart > least))
        throw std::invalid_argument(fmt::format(
            "majumdar_papapetrou: holes {} and {} are {:g} apart, inside each other's capture spheres (their "
            "masses over {:g}); keep them more than {:g} apart, or make them one hole of mass {:g}",
            j + 1, i + 1, apart, extreme_hole_capture_potential - 1.0, least, h.mass + o.mass));
    }
    mass_ += h.mass;
    extent_ = std::max(extent_, norm3(h.position));
    for (int k = 0; k < 3; ++k) dipole[k] += h.mass * h.position[k];
    spread += h.mass * (h.position[0] * h.position[0] + h.position[1] * h.position[1] + h.position[2] * h.position[2]);
  }
  far_field_radius_ = std::max(std::cbrt(spread / far_field_bending), std::sqrt(norm3(dipole) / far_field_bending));
}

std::vector<SpacetimeExample<MajumdarPapapetrou>> MajumdarPapapetrou::examples() {
  auto holes = [](std::initializer_list<PointHole> list) {
    Params p;
    for (const PointHole& h : list) p.holes.add(h);
    return MajumdarPapapetrou(p);
  };
  const double s = std::sqrt(3.0) / 2.0;
  return {
      // Three equal holes in a triangle in the plane z = 0.
      {holes({{0.3, {1.0, 0.0, 0.0}}, {0.3, {-0.5, s, 0.0}}, {0.3, {-0.5, -s, 0.0}}}), 2.1, 40.0},
      // Four unequal holes, not in a plane.
      {holes({{0.4, {1.0, 1.0, 0.0}}, {0.1, {-1.0, 1.0, 0.5}}, {0.25, {-1.0, -1.0, 0.0}}, {0.2, {1.0, -1.0, -0.5}}}),
       2.6, 40.0},
      // One hole off the origin.
      {holes({{0.5, {0.0, 0.5, 0.0}}}), 1.8, 40.0},
  };
}

template struct ExtremeHoles<MajumdarPapapetrou>;

}  // namespace lc
