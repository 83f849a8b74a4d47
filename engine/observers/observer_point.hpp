#pragma once
// What every observer kind gives for a time offset within the frame (an
// ObserverPoint: where it is and its frame there) and the checks every kind
// makes of where it stands, so that each kind's file says only what is its
// own (observers/observers.hpp is the registry).

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/tensor.hpp"
#include "eye/tetrad.hpp"
#include "spacetime/chart.hpp"

namespace lc {

// An observer's event and frame at one moment: the trace event, the same
// event in scene coordinates (exact where the shot gave it: on the spin
// axis) and its tetrad (e_0 its 4-velocity).
struct ObserverPoint {
  Vec4 event{};
  Vec4 scene_event{};
  Tetrad frame{};
};

// Where the script made an observer ("shot.lua:12"), for its errors.
inline std::string observer_where(const std::string& where) { return where.empty() ? std::string("observer") : where; }

// The distance of a scene point from the origin: r in a polar scene chart,
// |(x, y, z)| in a Cartesian one.
template <class S>
double distance_from_origin(const Vec4& p) {
  if constexpr (S::chart == SceneChart::polar) return std::abs(p[1]);
  else return std::hypot(p[1], p[2], p[3]);  // (no overflow for huge coordinates)
}

// Throws std::invalid_argument naming `where` when the scene point is
// farther from the origin than rays can be traced from.  `when` says which
// moment of a moving observer is meant ("at proper time 3 the fall is "),
// "" for one at rest.  Checked before a kind makes its frame: there the
// reason would show only as "not timelike" or "degenerates".
template <class S>
void check_observer_distance(const Vec4& scene_point, const std::string& where, std::string_view when) {
  const double d = distance_from_origin<S>(scene_point);
  if (!(d <= max_observer_distance))
    throw std::invalid_argument(fmt::format(
        "{}: observer: {}{:g} M from the origin, farther than rays can be traced from ({:g} M at most: double "
        "precision cannot resolve their steps near the hole); for a distant view put the observer at most that "
        "far away and narrow the camera's fov",
        observer_where(where), when, d, max_observer_distance));
}

// Throws std::invalid_argument naming `where` when the trace event x lies
// in the capture region, where rays are stopped; `hint` ends the message
// ("; a fall can be shown up to ...", or "").
template <class S>
void check_outside_capture(const S& st, const Vec4& x, const std::string& where, std::string_view hint) {
  if (st.captured(x))
    throw std::invalid_argument(fmt::format(
        "{}: observer: too close to a horizon (inside the capture region where rays are stopped{})",
        observer_where(where), hint));
}

}  // namespace lc
