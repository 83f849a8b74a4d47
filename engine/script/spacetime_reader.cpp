#include "script/spacetime_reader.hpp"

#include <fmt/format.h>

namespace lc {

Spacetime read_spacetime(lua::TableReader& t, KerrSchildSense sense) {
  const auto kind = t.optional_string("__kind");
  if (!kind)
    throw lua::FieldError(fmt::format(
        "{}: not a spacetime; make one with a constructor such as lc.kerr{{mass = 1, spin = 0.9}}, "
        "lc.dihole{{m1 = 0.4, m2 = 0.4}} or lc.minkowski()",
        t.context()));
  t.mark_known({"__where"});
  try {
    if (*kind == "kerr") {
      const double M = t.number("mass"), a = t.number("spin");
      t.finish();
      return Kerr(M, a, sense);
    }
    if (*kind == "dihole") {
      const double m1 = t.number("m1"), m2 = t.number("m2"), d = t.number("d");
      t.finish();
      return Dihole(m1, m2, d);
    }
    if (*kind == "minkowski") {
      t.finish();
      return Minkowski{};
    }
  } catch (const std::invalid_argument& e) {
    // Fields edited after construction can still be unphysical.
    throw lua::FieldError(fmt::format("{}: {}", t.context(), e.what()));
  }
  throw lua::FieldError(fmt::format("{}: a {} is not a spacetime", t.context(), *kind));
}

}  // namespace lc
