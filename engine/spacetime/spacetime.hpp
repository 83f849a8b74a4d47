#pragma once
// The registry of spacetimes: every one lightcone knows, one line each in
// the variant below, each a class satisfying SpacetimeModel
// (spacetime/model.hpp) in its own files.  Everything that works with "a
// spacetime" — the Lua constructors lc.<name>{...}, the scene reader, the
// descriptions and JSON, the geodesic spec reader, the scene builder, the
// generic self-test — goes through this variant and the model's members;
// none asks which spacetime it holds.

#include <string>
#include <string_view>
#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "core/registry.hpp"
#include "spacetime/dihole.hpp"
#include "spacetime/kerr.hpp"
#include "spacetime/minkowski.hpp"

namespace lc {

using Spacetime = std::variant<Minkowski, Kerr, Dihole>;

// One assertion per spacetime: the compiler's notes name the one that fails
// and the requirement it misses.
static_assert(every_kind<Spacetime>([]<class S>() {
  static_assert(SpacetimeModel<S>, "a registered spacetime must satisfy SpacetimeModel (spacetime/model.hpp)");
}));

// A type tag: for_each_spacetime_type calls f(TypeTag<S>{}) for each.
template <class T>
struct TypeTag {
  using type = T;
};
template <class F>
void for_each_spacetime_type(F&& f) {
  [&]<class... S>(std::variant<S...>*) { (f(TypeTag<S>{}), ...); }(static_cast<Spacetime*>(nullptr));
}

// Its name ("minkowski", "kerr", "dihole"): the Lua constructor's, in
// messages and output.
inline std::string_view spacetime_name(const Spacetime& s) {
  return std::visit([](const auto& st) { return std::decay_t<decltype(st)>::name; }, s);
}

inline SceneChart scene_chart(const Spacetime& s) {
  return std::visit([](const auto& st) { return std::decay_t<decltype(st)>::chart; }, s);
}

// The same spacetime in the chart regular where curves traced in direction
// d go (Kerr: its ingoing or outgoing Kerr–Schild form).
inline Spacetime for_tracing(const Spacetime& s, TimeDirection d) {
  return std::visit([d](const auto& st) -> Spacetime { return st.for_tracing(d); }, s);
}

// The chart camera rays are traced in: backwards in time.
inline Spacetime trace_chart(const Spacetime& s) { return for_tracing(s, TimeDirection::past); }

// Whether scene positions are polar {r, theta, phi}.
inline bool has_polar_scene(const Spacetime& s) { return scene_chart(s) == SceneChart::polar; }

// {"kind": name, <each declared parameter>: value}.
inline std::string spacetime_json(const Spacetime& s) {
  return std::visit(
      [](const auto& st) {
        using S = std::decay_t<decltype(st)>;
        return fmt::format("{{\"kind\": \"{}\"{}}}", S::name, fields_json(st.params()));
      },
      s);
}

// The spacetime and its exact parameters, e.g. "kerr(mass=1, spin=0.9)";
// equal strings mean the same spacetime (hex-float exact with exact = true).
inline std::string describe(const Spacetime& s, bool exact = false) {
  return std::visit(
      [exact](const auto& st) {
        using P = typename std::decay_t<decltype(st)>::Params;
        const P p = st.params();
        std::string out(std::decay_t<decltype(st)>::name);
        out += '(';
        bool first = true;
        for_each_field<P>([&](const auto& f) {
          const double v = p.*(f.member);
          out += fmt::format("{}{}={}", first ? "" : ", ", f.name, exact ? fmt::format("{:a}", v) : fmt::format("{:g}", v));
          first = false;
        });
        return out + ')';
      },
      s);
}

}  // namespace lc
