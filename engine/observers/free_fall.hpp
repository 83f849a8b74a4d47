#pragma once
// lc.free_fall{worldline = w, proper_time = tau}: the observer riding the
// worldline w (lc.worldline{...}, integrated once per shot) at proper time
// tau, its frame parallel-transported along it.  Its path is the worldline
// itself: an offset within the frame is proper time along it.

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "assets/shot_resources.hpp"
#include "core/fields.hpp"
#include "observers/observer_point.hpp"
#include "spacetime/spacetime_spec.hpp"
#include "worldline/worldline.hpp"
#include "worldline/worldline_spec.hpp"

namespace lc {

class FreeFall {
 public:
  static constexpr std::string_view name = "free_fall";  // lc.free_fall{...}
  static constexpr std::string_view title = "free-falling observer";  // in messages
  // Moving: no two of its frames are the same scene shifted in time.
  static constexpr bool fixed_in_space = false;
  // It keeps its own clock: the scene's `time` is refused, saying so.
  static constexpr std::string_view own_time = "its worldline";

  struct Params {
    double proper_time = 0.0;
    // Read by hand (script/scene_reader.cpp, read_placement): a worldline
    // is a value made by lc.worldline{...}, not a declared field's type.
    WorldlineSpec worldline;
    std::string where{};  // "shot.lua:12", where the script made it (errors only)
    static constexpr auto fields = std::tuple{
        field("proper_time", &Params::proper_time, std::optional<double>{}, at_least(0.0), std::nullopt,
              "where on the worldline: proper time since its start, at most its duration", "M"),
    };
    // What the declared fields leave out: the worldline, by name (for the
    // reader's check of unknown fields) ...
    static constexpr std::array<std::string_view, 1> extra_fields = {"worldline"};
    // ... for the reference (lightcone fields) ...
    static constexpr std::string_view extra_doc =
        "And `worldline = w` (required): the lc.worldline{...} it rides; see Worldlines.";
    // ... as JSON ...
    std::string extra_json(bool) const { return ", \"worldline\": " + worldline.json(); }
    // ... and exactly.
    std::string extra_key() const { return " along " + worldline.key(); }
    // Its clock: proper time along the worldline.
    double clock() const { return proper_time; }
    // Where on the worldline it may be.
    void validate() const {
      if (proper_time > worldline.duration)
        throw std::invalid_argument(
            fmt::format("proper_time {} is outside the worldline's [0, {}]", proper_time, worldline.duration));
    }
  };

  // On p's worldline (from `res`, integrated once per shot) in the spacetime
  // st (its trace chart).  Throws std::invalid_argument for a worldline made
  // in another spacetime or one that does not integrate (naming the
  // worldline's line), and for a place rays cannot be traced from (naming
  // p.where); ObserverError where its frame cannot be carried to tau.
  template <class S>
  FreeFall(const Params& p, const S& st, ShotResources& res) : tau_(p.proper_time) {
    const WorldlineSpec& w = p.worldline;
    if (describe(w.spacetime, true) != describe(Spacetime(st), true))
      throw std::invalid_argument(fmt::format(
          "{}: the observer's worldline ({}) was made in {}, but this frame's spacetime is {}; a worldline only "
          "makes sense in the spacetime it was integrated in",
          w.where, w.where, describe(w.spacetime), describe(Spacetime(st))));
    worldline_ = res.worldline(w);
    now_ = point(st, tau_);
    check_observer_distance<S>(now_.scene_event, p.where, fmt::format("at proper time {:g} the fall is ", tau_));
    check_outside_capture(st, now_.event, p.where, "; a fall can be shown up to just outside the horizon");
  }

  // Where it is dtau of proper time after the frame's moment (the frame's
  // own point for dtau = 0, exactly): Worldline::at_proper_time(tau +
  // dtau), clamped as that is to the worldline's [0, duration].  May throw
  // ObserverError where the frame cannot be carried there.
  template <class S>
  ObserverPoint at(const S& st, double dtau) const {
    return dtau == 0.0 ? now_ : point(st, tau_ + dtau);
  }

 private:
  template <class S>
  ObserverPoint point(const S& st, double tau) const {
    const WorldlineEvent ev = worldline_->at_proper_time(tau);
    return {ev.x, st.scene_from_trace(ev.x), ev.frame};
  }

  std::shared_ptr<const Worldline> worldline_;
  double tau_;
  ObserverPoint now_;
};

}  // namespace lc
