#pragma once
// The registry of observer kinds: every kind lightcone knows, one line each,
// each a class satisfying ObserverModel in its own file.  A scene holds what
// a shot gave (ObserverSpec: lc.<name>{...}); the built scene holds the
// observer as a path (ObserverPath): the eye (eye/eye.hpp) at any time
// offset within the frame, so a camera sample with its own time has a
// place to start from.

#include <concepts>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "assets/shot_resources.hpp"
#include "core/registry.hpp"
#include "eye/eye.hpp"
#include "eye/tetrad.hpp"
#include "observers/circular_orbit.hpp"
#include "observers/free_fall.hpp"
#include "observers/observer_point.hpp"
#include "observers/static_observer.hpp"
#include "observers/zamo.hpp"
#include "spacetime/chart.hpp"

namespace lc {

// What an observer kind is, in the spacetime S (its trace chart): a name
// (its Lua constructor lc.<name>{...}), a title for messages ("static
// observer"), whether it is fixed in space (then frames that differ only in
// its time are one scene shifted in time and may share rays: still_key),
// Params with declared fields and `where` (the script line that made it,
// for errors), and either a Params::set_time(t) that the scene's `time`
// field calls or a static `own_time` that says where its clock comes from
// instead; a constructor from its parameters, the spacetime and the shot's
// resources, which checks where it stands (throwing std::invalid_argument,
// or ObserverError where its frame cannot exist), and its event and frame
// at a time offset within the frame (offset 0: the frame's own moment).
template <class O, class S>
concept ObserverModel = requires(const O& o, const typename O::Params& p, const S& st, ShotResources& res, double dt) {
  requires std::same_as<std::remove_cv_t<decltype(O::name)>, std::string_view>;
  requires std::same_as<std::remove_cv_t<decltype(O::title)>, std::string_view>;
  requires std::same_as<std::remove_cv_t<decltype(O::fixed_in_space)>, bool>;
  requires HasFields<typename O::Params>;
  requires std::same_as<decltype(p.where), std::string>;
  requires requires(typename O::Params& q) { q.set_time(dt); } ||
               std::same_as<std::remove_cv_t<decltype(O::own_time)>, std::string_view>;
  O(p, st, res);
  { o.at(st, dt) } -> std::same_as<ObserverPoint>;
};

// Every observer kind, one line each.
using ObserverRegistry = Registry<StaticObserver, Zamo, FreeFall, CircularOrbit>;

// The observer a shot asked for: one of the registered kinds' parameters.
using ObserverSpec = ObserverRegistry::Spec;

// Where the script made it ("shot.lua:12"; "observer" if unknown).
inline std::string observer_where(const ObserverSpec& spec) {
  return observer_where(std::visit([](const auto& p) -> const std::string& { return p.where; }, spec));
}

// Whether the kind is fixed in space (ObserverModel).
inline bool observer_fixed_in_space(const ObserverSpec& spec) {
  bool fixed = false;
  ObserverRegistry::for_each([&](auto* kind) {
    using O = std::remove_pointer_t<decltype(kind)>;
    if (std::holds_alternative<typename O::Params>(spec)) fixed = O::fixed_in_space;
  });
  return fixed;
}

// The observer's clock: scene time for one at rest, proper time for a fall.
inline double observer_clock(const ObserverSpec& spec) {
  return std::visit([](const auto& p) { return p.clock(); }, spec);
}

// The scene's `time` given to the observer: "" where its kind takes it,
// else why not ("a free-falling observer's time comes from its worldline;
// remove 'time'").
inline std::string set_scene_time(ObserverSpec& spec, double t) {
  std::string refused;
  ObserverRegistry::for_each([&](auto* kind) {
    using O = std::remove_pointer_t<decltype(kind)>;
    auto* p = std::get_if<typename O::Params>(&spec);
    if (!p) return;
    if constexpr (requires { p->set_time(t); })
      p->set_time(t);
    else
      refused = fmt::format("a {}'s time comes from {}; remove 'time'", O::title, O::own_time);
  });
  return refused;
}

// The observer of a frame as a path in the spacetime S (its trace chart):
// the eye at a time offset within the frame (scene time for an observer at
// rest, proper time for a free fall).  at(0) is the frame's own eye,
// worked out once; other offsets are worked out when asked.  A default one
// (a scene not made by build_scene) has no eye.
template <class S>
class ObserverPath {
 public:
  ObserverPath() = default;

  // The observer of `spec` in st, with the ZAMO's 4-velocity in each eye
  // where `with_reference` (the light model splits g: light/light.hpp).
  // Throws std::invalid_argument naming the script's line where it cannot
  // stand (ObserverError from its frame becomes "<where>: observer: ...").
  ObserverPath(const ObserverSpec& spec, const S& st, ShotResources& res, bool with_reference) {
    try {
      built_.emplace(Built{st, ObserverRegistry::build(spec, st, res), with_reference});
    } catch (const ObserverError& e) {
      throw std::invalid_argument(fmt::format("{}: observer: {}", observer_where(spec), e.what()));
    }
    now_ = eye(0.0);
  }

  // The eye dt after the frame's moment (its own clock: scene time for an
  // observer at rest, proper time for a free fall).  May throw
  // ObserverError where the observer's frame cannot exist at that time.
  Eye at(double dt) const {
    if (!built_) throw std::logic_error("ObserverPath::at: this scene's observer was never built (build_scene)");
    return dt == 0.0 ? now_ : eye(dt);
  }

 private:
  struct Built {
    S spacetime;
    ObserverRegistry::Kinds kind;
    bool with_reference;
  };

  Eye eye(double dt) const {
    const S& st = built_->spacetime;
    const ObserverPoint pt = std::visit([&](const auto& o) { return o.at(st, dt); }, built_->kind);
    Eye e;
    e.event = pt.event;
    e.scene_event = pt.scene_event;
    double r_unused, phi_unused;
    scene_polar(st, pt.event, e.time, r_unused, phi_unused);
    e.metric = st.metric(pt.event);
    e.frame = pt.frame;
    if (built_->with_reference) e.reference = zamo_velocity(st, pt.event);
    return e;
  }

  std::optional<Built> built_;
  Eye now_{};
};

}  // namespace lc
