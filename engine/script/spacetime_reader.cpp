#include "script/spacetime_reader.hpp"

#include <fmt/format.h>

#include "script/field_reader.hpp"
#include "spacetime/spacetime.hpp"

namespace lc {

// Every registered spacetime's constructor, by name: its declared
// parameters read, then the class's own checks.
Spacetime read_spacetime(lua::TableReader& t) {
  const auto asked = t.optional_string("__kind");
  if (!asked) {
    std::string examples;
    SpacetimeRegistry::for_each([&](auto* kind) {
      examples += fmt::format("{}lc.{}{{...}}", examples.empty() ? "" : ", ", std::remove_pointer_t<decltype(kind)>::name);
    });
    throw lua::FieldError(
        fmt::format("{}: not a spacetime; make one with a constructor: {}", t.context(), examples));
  }
  t.mark_known({"__where"});
  std::optional<Spacetime> out;
  SpacetimeRegistry::for_each([&](auto* kind) {
    using S = std::remove_pointer_t<decltype(kind)>;
    if (out || *asked != S::name) return;
    typename S::Params p;
    read_fields(t, p);
    t.finish();
    try {
      out = S(p);
    } catch (const std::invalid_argument& e) {
      // The spacetime classes prefix their messages with their name; the
      // context already names it.
      std::string_view msg = e.what();
      if (msg.starts_with(std::string(S::name) + ": ")) msg.remove_prefix(S::name.size() + 2);
      throw lua::FieldError(fmt::format("{}: {}", t.context(), msg));
    }
  });
  if (!out) throw lua::FieldError(fmt::format("{}: a {} is not a spacetime", t.context(), *asked));
  return *out;
}

}  // namespace lc
