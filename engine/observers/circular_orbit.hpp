#pragma once
// lc.circular_orbit{r, phi, t}: an observer riding, in the equatorial
// plane at radius r, the circular orbit matter there moves on, as a disk's
// does (spacetime/equatorial_flow.hpp): Keplerian and co-rotating with a Kerr or
// Kerr–Newman hole outside its ISCO, about the axis in the dihole's plane
// z = 0.  At scene time t it is at longitude phi + Omega t.  Its frame is
// the static frame there (the ZAMO's inside an ergoregion) boosted to its
// velocity, which is along e_phi: the boost leaves e_r and e_theta as
// they are, so a camera "looking at the hole" (forward = -e_r) still does,
// and the orbit's motion shows as aberration and Doppler shift.  Its clock
// is scene time; it moves, so no two of its frames share rays.

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "assets/shot_resources.hpp"
#include "core/constants.hpp"
#include "core/fields.hpp"
#include "eye/tetrad.hpp"
#include "observers/observer_point.hpp"
#include "spacetime/equatorial_flow.hpp"

namespace lc {

class CircularOrbit {
 public:
  static constexpr std::string_view name = "circular_orbit";  // lc.circular_orbit{...}
  static constexpr std::string_view title = "circular-orbit observer";  // in messages
  static constexpr bool fixed_in_space = false;

  struct Params {
    double r = 0.0, phi = 0.0, t = 0.0;
    std::string where{};  // "shot.lua:12", where the script made it (errors only)
    static constexpr auto fields = std::tuple{
        field("r", &Params::r, std::optional<double>{}, above(0.0), std::nullopt,
              "the orbit's radius in the equatorial plane (Kerr: Boyer–Lindquist r, outside the ISCO; dihole: "
              "the distance from the axis in the plane z = 0)",
              "M"),
        field("phi", &Params::phi, std::optional<double>{0.0}, std::nullopt, std::nullopt,
              "its longitude at scene time 0; it moves towards +phi with the orbit's angular velocity", "degrees"),
        field("t", &Params::t, std::optional<double>{0.0}, std::nullopt, std::nullopt,
              "the scene time, its clock (the scene's `time` replaces it)", "M"),
    };
    void set_time(double time) { t = time; }
    double clock() const { return t; }
  };

  // On the orbit of p.r in the spacetime st (its trace chart), at p.t.
  // Throws std::invalid_argument naming p.where where st has no circular
  // orbits worked out, where there is none at r (inside a Kerr hole's ISCO
  // its matter plunges; the dihole's may be faster than light) or rays
  // cannot be traced from.
  template <class S>
  CircularOrbit(const Params& p, const S& st, ShotResources&) : r_(p.r), phi0_(p.phi * degree), t_(p.t) {
    if constexpr (!EquatorialFlow<S>::orbits) {
      throw std::invalid_argument(fmt::format(
          "{}: observer: lightcone has no circular orbits in {} (it has them where a disk's matter orbits: kerr, "
          "with or without a charge, and the dihole)",
          observer_where(p.where), S::name));
    } else {
      const Vec4 s = scene_point<S>(0.0);
      check_observer_distance<S>(s, p.where, "");
      const Vec4 x = st.trace_from_scene(s);
      check_outside_capture(st, x, p.where, "");
      const Vec4 su = st.scene_vector(x, EquatorialFlow<S>::velocity(st, x));
      double radial;
      if constexpr (S::chart == SceneChart::polar) {
        omega_ = su[3] / su[0];
        radial = su[1] / su[0];
      } else {
        omega_ = (s[1] * su[2] - s[2] * su[1]) / (r_ * r_ * su[0]);
        radial = (s[1] * su[1] + s[2] * su[2]) / (r_ * su[0]);
      }
      if (!(std::abs(radial) < 1e-9) || !(omega_ != 0.0))
        throw std::invalid_argument(fmt::format(
            "{}: observer: no circular orbit at r = {:g} in {} (inside the innermost stable one a disk's matter "
            "plunges; between two holes it may be none at all); put it farther out",
            observer_where(p.where), r_, S::name));
      now_ = point(st, t_);
    }
  }

  // Where it is dt of scene time after the frame's moment (the frame's own
  // point for dt = 0, exactly).
  template <class S>
  ObserverPoint at(const S& st, double dt) const {
    return dt == 0.0 ? now_ : point(st, t_ + dt);
  }

  // Its angular velocity d phi / dt in scene time.
  double angular_velocity() const { return omega_; }

 private:
  template <class S>
  Vec4 scene_point(double t) const {
    const double phi = phi0_ + omega_ * t;
    if constexpr (S::chart == SceneChart::polar)
      return {t, r_, 0.5 * pi, phi};
    else
      return {t, r_ * std::cos(phi), r_ * std::sin(phi), 0.0};
  }

  template <class S>
  ObserverPoint point(const S& st, double t) const {
    const Vec4 s = scene_point<S>(t);
    const Vec4 x = st.trace_from_scene(s);
    const Tetrad rest = velocity_reference_frame(st, s);
    const Vec4 u = EquatorialFlow<S>::velocity(st, x);
    return {x, s, boost(rest, relative_velocity(st.metric(x), rest, u))};
  }

  double r_, phi0_, t_;
  double omega_ = 0.0;
  ObserverPoint now_;
};

}  // namespace lc
