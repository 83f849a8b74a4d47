#pragma once
// lc.disk{...}: the infinitely thin equatorial accretion disk, inner <= r <=
// outer in the chart's radius (Boyer–Lindquist r for Kerr), checkered in r
// (rings) and phi (sectors), or glowing as a Novikov–Thorne disk seen
// through the frequency shift g (docs/light.md).  Rays meet it where they
// cross the plane z = 0.

#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "core/color.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/hit_kind.hpp"
#include "light/blackbody.hpp"
#include "light/light.hpp"
#include "light/novikov_thorne.hpp"
#include "objects/disk_params.hpp"
#include "objects/disk_physics.hpp"
#include "objects/step_query.hpp"
#include "objects/surface_point.hpp"
#include "spacetime/chart.hpp"

namespace lc {

class ShotResources;

class Disk {
 public:
  static constexpr std::string_view name = DiskParams::name;
  static constexpr HitKind hit_kind = HitKind{1};  // hit.kind 1
  // The BL–Mino path finds it at its own equatorial crossings (render/kerr_fast_path_ray.hpp).
  static constexpr bool in_fast_path = true;

  using Params = DiskParams;

  // In the spacetime st, with colour tables from `res`.  Throws
  // std::invalid_argument for a glowing disk where st has no Novikov–Thorne
  // disk.
  template <class S>
  Disk(const Params& p, const S& st, ShotResources& res, const Vec4&) : p_(p) {
    if (p.glows()) glow(DiskPhysics<S>::flux(st), res);
  }
  // A checkered disk.
  explicit Disk(const Params& p) : p_(p) {}

  // How far it reaches, in st's flight measure (SpacetimeEnds::flight_reach),
  // from the trace-chart radii of its edges in the plane: at most the outer
  // edge's, or outer + |M| (Kerr–Schild's radius exceeds Boyer–Lindquist's
  // by up to ~M), whichever is larger.  Assumes the trace chart's radius
  // grows with the scene's r in the plane, as every chart's here does.
  template <class S>
  double reach(const S& st) const {
    const auto chart_radius = [&](double r) {
      const Vec4 x = st.trace_from_scene(S::chart == SceneChart::polar ? Vec4{0.0, r, 0.5 * pi, 0.0} : Vec4{0.0, r, 0.0, 0.0});
      return std::sqrt(x[1] * x[1] + x[2] * x[2] + x[3] * x[3]);
    };
    const double hi = std::max(p_.outer + std::abs(st.asymptotic_mass()), chart_radius(p_.outer));
    return st.flight_reach(std::min(chart_radius(p_.inner), hi), hi);
  }
  bool covers(double r) const { return r >= p_.inner && r <= p_.outer; }

  // Colour at the chart's (r, phi), r in [inner, outer], phi in [0, 2 pi),
  // seen as `shift` says: a glowing disk's ring at temperature T seen
  // shifted by g is a blackbody at g f T (I_nu / nu^3 is invariant, so a
  // blackbody stays one); else the checker.
  Color color(double r, double phi, const SeenShift& shift) const {
    if (colors_) {
      Color c = (*colors_)(shift.color * p_.color_correction * ring_temperature(r));
      const float k = shift.beaming != shift.color ? scale_ * shift.extra_beaming() : scale_;
      if (k != 1.0f)
        for (float& v : c) v *= k;
      return c;
    }
    const long ring = static_cast<long>(std::floor((r - p_.inner) / (p_.outer - p_.inner) * p_.rings));
    const long sector = static_cast<long>(std::floor(phi / two_pi * p_.sectors));
    return shift.texture(checker(ring, sector, p_.colors));
  }

  // Where the test's step crosses the plane within the disk, if before the
  // earliest hit found so far.
  template <class S>
  std::optional<double> first_hit(const S& st, StepTest& t, std::size_t) const {
    if (!t.crosses_equator()) return std::nullopt;
    const double lz = t.equator_crossing();
    if (!(lz < t.best())) return std::nullopt;
    const RayState y = t.step().at(lz);
    double time, r, phi;
    scene_polar(st, {y[0], y[1], y[2], y[3]}, time, r, phi);
    if (!covers(r)) return std::nullopt;
    return lz;
  }

  // Where the ray that ended at the trace event y met it: the chart's r
  // and phi.
  template <class S>
  SurfacePoint surface_at(const S& st, const RayState& y) const {
    double time, r, phi;
    scene_polar(st, {y[0], y[1], y[2], y[3]}, time, r, phi);
    return {r, phi};
  }
  Color color_at(const SurfacePoint& at, const SeenShift& shift) const { return color(at.u, at.v, shift); }

  // Its matter's 4-velocity at the trace event y (objects/disk_physics.hpp).
  template <class S>
  Vec4 emitter_velocity(const S& st, const RayState& y) const {
    return DiskPhysics<S>::velocity(st, {y[0], y[1], y[2], y[3]});
  }

 private:
  // T(r) = T_max (F(r) / F_max)^(1/4): each ring radiates its flux as a
  // blackbody (Stefan–Boltzmann).
  double ring_temperature(double r) const { return t_max_ * std::sqrt(std::sqrt((*flux_)(r) / flux_max_)); }
  void glow(const std::optional<NovikovThorneFlux>& flux, ShotResources& res);

  Params p_;
  std::optional<NovikovThorneFlux> flux_;  // a glowing disk's
  double flux_max_ = 0.0;
  double t_max_ = 0.0;  // the hottest ring's temperature (K)
  float scale_ = 1.0f;  // the colour table's values to the light's units
  std::shared_ptr<const BlackbodyColors> colors_;
};

}  // namespace lc
