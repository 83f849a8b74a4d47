#pragma once
// lc.sphere{...}: a checkered sphere of proper radius `radius`, defined in
// the local frame of a tetrad that is held at rest at `position` or falls
// freely along `worldline`; the checker's pole is the frame's third leg (z
// for a sphere at rest in a Cartesian scene).  Rays are tested against it
// only where the box its centre keeps over the step's time range (the
// paper's spacetime tube) allows (objects/sphere_intersection.hpp).

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "core/color.hpp"
#include "light/light.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/hit_kind.hpp"
#include "core/json.hpp"
#include "objects/bounded_body.hpp"
#include "objects/surface_point.hpp"
#include "objects/sphere_body.hpp"
#include "objects/sphere_intersection.hpp"
#include "objects/sphere_params.hpp"
#include "objects/step_query.hpp"
#include "assets/shot_resources.hpp"
#include "worldline/placement.hpp"
#include "worldline/worldline.hpp"
#include "worldline/worldline_spec.hpp"
#include "spacetime/chart.hpp"

namespace lc {

class Sphere : public SphereBody {
 public:
  static constexpr std::string_view name = SphereParams::name;
  static constexpr HitKind hit_kind = HitKind{3};  // hit.kind 3
  // Its worldline and frame live in the trace chart: only the general path.
  static constexpr bool in_fast_path = false;

  using Params = SphereParams;

  // In the spacetime st (its trace chart), with worldlines from `res`, for a
  // frame whose observer is at the trace event `observer`.  Throws
  // std::invalid_argument for a worldline from another spacetime, a rest
  // position without a static observer, or a worldline that ends before
  // this frame's rays may last meet the sphere.
  template <class S>
  Sphere(const Params& p, const S& st, ShotResources& res, const Vec4& observer) : p_(p) {
    radius = p.radius;
    if (const WorldlineSpec* w = p.placement.worldline()) {
      if (describe(w->spacetime, true) != describe(Spacetime(st), true))
        throw std::invalid_argument(fmt::format(
            "{}: a sphere's worldline ({}) was made in {}, but this frame's spacetime is {}; a worldline only makes "
            "sense in the spacetime it was integrated in",
            w->where, w->where, describe(w->spacetime), describe(Spacetime(st))));
      worldline = res.worldline(*w);
    } else {
      rest_position = st.trace_from_scene(*p.placement.rest());
      try {
        rest_frame = static_frame(st, *p.placement.rest());
      } catch (const ObserverError& e) {
        throw std::invalid_argument(fmt::format("sphere at rest: {}", e.what()));
      }
    }
    // At rest the centre does not move: the stretch alone, exact but for
    // rounding.
    tube = worldline ? worldline->coordinate_extent(radius) : (1.0 + 1e-9) * rest_space_span(rest_frame).stretch * radius;
    bounds(-1e300, 1e300, life_lo, life_hi);
    top_speed = worldline ? worldline->top_coordinate_speed() : 0.0;
    if (worldline) check_worldline_lasts(observer);
  }

  // How far anything of it ever is, in st's flight measure
  // (SpacetimeEnds::flight_reach): from the shell of trace-chart radii its
  // boxes span.
  template <class S>
  double reach(const S& st) const {
    return st.flight_reach(body_nearest(*this), body_reach(*this));
  }

  // The first entry into it within the test's step, if any and before the
  // earliest hit found so far.  A step that comes near where its centre
  // ever is narrows the ray's reuse window (narrow_reuse_window,
  // objects/bounded_body.hpp).
  template <class S>
  std::optional<double> first_hit(const S& st, StepTest& t, std::size_t index) const {
    const BodyNear near = body_near_step(*this, t.step());
    if (near.reach == BodyReach::never) return std::nullopt;
    narrow_reuse_window(*this, t, near);
    if (near.reach == BodyReach::not_now) return std::nullopt;
    const auto l = detail::sphere_entry(st, *this, t.step(), t.hull(), near.lo, near.hi, t.warm_start(index));
    if (l && *l < t.best()) return l;
    return std::nullopt;
  }

  // Where the ray meets it (the trace event y): its own polar angles, pole
  // along the frame's third leg, phi in [0, 2 pi).
  template <class S>
  SurfacePoint surface_at(const S& st, const RayState& y) const {
    const Vec3 xi = detail::sphere_local(st, *this, {y[0], y[1], y[2], y[3]});
    const double th = std::acos(std::clamp(xi[2] / norm3(xi), -1.0, 1.0));
    double ph = std::atan2(xi[1], xi[0]);
    if (ph < 0) ph += two_pi;
    return {th, ph};
  }
  // Its colour there, seen as `shift` says: a checker in those angles.
  Color color_at(const SurfacePoint& at, const SeenShift& shift) const {
    return shift.texture(
        checker(static_cast<long>(at.u / pi * p_.rows), static_cast<long>(at.v / two_pi * p_.columns), p_.colors));
  }

  // Its matter's 4-velocity where the ray meets it (the trace event y): the
  // body moves rigidly, so the centre's 4-velocity at y's coordinate time,
  // normalised in the metric at y (the two points are a radius apart).
  template <class S>
  Vec4 emitter_velocity(const S& st, const RayState& y) const {
    Vec4 c, u;
    centre(y[0], c, u);
    const Vec4 x = {y[0], y[1], y[2], y[3]};
    const double n = -dot(mat_vec(st.metric(x), u), u);
    return n > 0.0 ? (1.0 / std::sqrt(n)) * u : u;
  }

 private:
  // A free-falling sphere's worldline must last as long as this frame's rays
  // may meet it: after its end the body would be nowhere (its centre is held
  // at the last event, whose time no ray point shares).  Light reaches the
  // observer at t from no earlier than t minus the Euclidean coordinate
  // distance, since in these charts (Kerr–Schild g = eta + f l l with f >= 0,
  // the dihole's isotropic U^2 >= 1) light is no faster than 1 in
  // coordinates; the centre's box grown by the tube's radius holds the
  // sphere.
  void check_worldline_lasts(const Vec4& observer) const {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double lo = life_lo[k] - tube_radius(), hi = life_hi[k] + tube_radius();
      const double out = std::max({lo - observer[k + 1], observer[k + 1] - hi, 0.0});
      d2 += out * out;
    }
    const double latest = observer[0] - std::sqrt(d2);
    if (latest <= worldline->end_time()) return;
    throw std::invalid_argument(fmt::format(
        "a sphere's worldline ({}) ends {:.4g} M of coordinate time before this frame's rays may last meet the sphere "
        "(after it the sphere would vanish): lengthen its duration ({:.6g} of proper time)",
        p_.placement.worldline()->where, latest - worldline->end_time(), worldline->duration()));
  }

  Params p_;
};

}  // namespace lc
