#pragma once
// What the observers held at one place (the static observer, the ZAMO)
// share: their parameters, a scene position written as the constructor's
// own fields (lc.static_observer{r = 30, theta = 80, phi = 0}), and their
// path, which stays at that place while its time runs.  Each kind gives
// its name, its title for messages and its tetrad at a scene point
// (Kind::tetrad(st, scene_point)).

#include <array>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "assets/shot_resources.hpp"
#include "core/json.hpp"
#include "core/tensor.hpp"
#include "observers/observer_point.hpp"

namespace lc {

// The parameters of an observer at rest of kind Kind (one type per kind, so
// the registry's variant tells them apart).  The position is read by hand
// (script/scene_reader.cpp, read_placement): it is the table's own
// {t, r, theta, phi} or {t, x, y, z}, not a field holding a table.
template <class Kind>
struct AtRestParams {
  Vec4 position{};    // scene coordinates (angles in radians); [0] is the scene time
  std::string where{};  // "shot.lua:12", where the script made it (errors only: not in the key or the JSON)
  static constexpr auto fields = std::tuple{};
  // What the declared fields leave out: the position, by its names (for
  // the reader's check of unknown fields) ...
  static constexpr std::array<std::string_view, 7> extra_fields = {"t", "r", "theta", "phi", "x", "y", "z"};
  // ... for the reference (lightcone fields) ...
  static constexpr std::string_view extra_doc =
      "Its fields are its position: `r, theta, phi` (Kerr: Boyer–Lindquist; Kottler: static; a wormhole: r the signed distance from the throat; degrees) or `x, y, z` (dihole, "
      "Majumdar–Papapetrou, Minkowski), all three required, and `t`, the scene time (default 0; the scene's `time` replaces it); see "
      "Positions.";
  // ... as JSON ...
  std::string extra_json(bool polar) const { return ", \"position\": " + json_position(position, polar); }
  // ... and exactly, without the time: frames that differ only in it are
  // the same scene shifted in time (scene/still_key.hpp).
  std::string extra_key() const { return fmt::format(" at {:a} {:a} {:a}", position[1], position[2], position[3]); }
  // The scene's `time` field.
  void set_time(double t) { position[0] = t; }
  // Its clock: the scene time (an exact scene key holds it: scene_key).
  double clock() const { return position[0]; }
};

// The path of an observer held at one place: the same scene position at
// every offset, its time moved by the offset, Kind's tetrad there.
template <class Kind>
class AtRestObserver {
 public:
  using Params = AtRestParams<Kind>;
  static constexpr bool fixed_in_space = true;

  // At p's position in the spacetime st (its trace chart).  Throws
  // std::invalid_argument naming p.where for a place rays cannot be traced
  // from (too far, the origin, inside the capture region) and ObserverError
  // where Kind's frame cannot exist (inside a horizon or, for a static
  // observer, the ergoregion).
  template <class S>
  AtRestObserver(const Params& p, const S& st, ShotResources&) : position_(p.position) {
    check_observer_distance<S>(position_, p.where, "");
    if (distance_from_origin<S>(position_) == 0.0)
      throw std::invalid_argument(fmt::format(
          "{}: observer: at the origin a {} has no view 'at the hole' (forward = -e_r has no direction there): "
          "move it off the origin, and aim with lc.camera's yaw and pitch",
          observer_where(p.where), Kind::title));
    now_ = point(st, position_);
    check_outside_capture(st, now_.event, p.where, "");
  }

  // Where it is dt of scene time after the frame's time (the frame's own
  // point for dt = 0, exactly).  May throw ObserverError where the frame
  // cannot exist then (a spacetime that changes in time).
  template <class S>
  ObserverPoint at(const S& st, double dt) const {
    if (dt == 0.0) return now_;  // (and -0.0 + 0.0 would turn a -0 time into +0)
    Vec4 p = position_;
    p[0] += dt;
    return point(st, p);
  }

 private:
  template <class S>
  static ObserverPoint point(const S& st, const Vec4& scene_point) {
    return {st.trace_from_scene(scene_point), scene_point, Kind::tetrad(st, scene_point)};
  }

  Vec4 position_;
  ObserverPoint now_;
};

}  // namespace lc
