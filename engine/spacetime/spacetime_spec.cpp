#include "spacetime/spacetime_spec.hpp"

#include <type_traits>
#include <variant>

#include <fmt/format.h>

#include "core/fields.hpp"
#include "core/spec_box_impl.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

namespace {

// A parameter's value in describe(): a number as %a (exact) or %g, a list
// of holes by its own text.
std::string describe_text(double v, bool exact) { return exact ? fmt::format("{:a}", v) : fmt::format("{:g}", v); }
std::string describe_text(const HoleList& v, bool exact) { return exact ? field_text(v, true) : people_text(v); }

}  // namespace

// The box's members, and for each spacetime how a box is made from it and
// read back: one line per spacetime, as spacetime/spacetime.hpp lists them.
// A spacetime missing here is a link error naming
// SpecAccess<SpacetimeKinds, It>.
template class SpecBox<SpacetimeKinds>;
template struct SpecAccess<SpacetimeKinds, Minkowski>;
template struct SpecAccess<SpacetimeKinds, Kerr>;
template struct SpecAccess<SpacetimeKinds, Dihole>;
template struct SpecAccess<SpacetimeKinds, MajumdarPapapetrou>;
template struct SpecAccess<SpacetimeKinds, Kottler>;
template struct SpecAccess<SpacetimeKinds, EllisWormhole>;
template struct SpecAccess<SpacetimeKinds, InterstellarWormhole>;

std::string_view spacetime_name(const Spacetime& s) {
  return std::visit([](const auto& st) { return std::decay_t<decltype(st)>::name; }, s.kinds());
}

SceneChart scene_chart(const Spacetime& s) {
  return std::visit([](const auto& st) { return std::decay_t<decltype(st)>::chart; }, s.kinds());
}

bool scene_radius_is_signed(const Spacetime& s) {
  return std::visit([](const auto& st) { return scene_radius_is_signed<std::decay_t<decltype(st)>>(); }, s.kinds());
}

std::span<const SpacetimeEnd> spacetime_ends(const Spacetime& s) {
  return std::visit([](const auto& st) { return std::span<const SpacetimeEnd>(std::decay_t<decltype(st)>::ends); },
                    s.kinds());
}

Spacetime for_tracing(const Spacetime& s, TimeDirection d) {
  return std::visit([d](const auto& st) -> Spacetime { return Spacetime(st.for_tracing(d)); }, s.kinds());
}

Spacetime trace_chart(const Spacetime& s) { return for_tracing(s, TimeDirection::past); }

bool has_polar_scene(const Spacetime& s) { return scene_chart(s) == SceneChart::polar; }

std::string spacetime_json(const Spacetime& s) {
  return std::visit(
      [](const auto& st) {
        using S = std::decay_t<decltype(st)>;
        return fmt::format("{{\"kind\": \"{}\"{}}}", S::name, fields_json(st.params()));
      },
      s.kinds());
}

std::string spacetimes_in_chart(SceneChart c) {
  std::string out;
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    if (S::chart == c) out += fmt::format("{}{}", out.empty() ? "" : ", ", S::name);
  });
  return out;
}

Vec4 scene_from_trace(const Spacetime& s, const Vec4& x) {
  return std::visit([&](const auto& st) { return st.scene_from_trace(x); }, s.kinds());
}

Vec4 scene_vector(const Spacetime& s, const Vec4& x, const Vec4& u) {
  return std::visit([&](const auto& st) { return st.scene_vector(x, u); }, s.kinds());
}

std::string describe(const Spacetime& s, bool exact) {
  return std::visit(
      [exact](const auto& st) {
        using P = typename std::decay_t<decltype(st)>::Params;
        const P p = st.params();
        std::string out(std::decay_t<decltype(st)>::name);
        out += '(';
        bool first = true;
        for_each_field<P>([&](const auto& f) {
          const auto& v = p.*(f.member);
          if (left_out(f, v)) return;
          out += fmt::format("{}{}={}", first ? "" : ", ", f.name, describe_text(v, exact));
          first = false;
        });
        return out + ')';
      },
      s.kinds());
}

}  // namespace lc
