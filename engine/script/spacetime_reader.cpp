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
      const double M = t.number("mass"), a = t.number_or("spin", 0.0);
      t.finish();
      return Kerr(M, a, sense);
    }
    if (*kind == "dihole") {
      const double m1 = t.number("m1"), m2 = t.number("m2"), d = t.number_or("d", 1.0);
      t.finish();
      return Dihole(m1, m2, d);
    }
    if (*kind == "minkowski") {
      t.finish();
      return Minkowski{};
    }
  } catch (const std::invalid_argument& e) {
    // The spacetime classes prefix their messages with their kind; the
    // context already names it.
    std::string_view msg = e.what();
    if (msg.starts_with(*kind + ": ")) msg.remove_prefix(kind->size() + 2);
    throw lua::FieldError(fmt::format("{}: {}", t.context(), msg));
  }
  throw lua::FieldError(fmt::format("{}: a {} is not a spacetime", t.context(), *kind));
}

}  // namespace lc
