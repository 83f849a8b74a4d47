#include "spacetime/spacetime.hpp"

#include <fmt/format.h>

namespace lc {

std::string spacetime_name(const Spacetime& s) {
  struct Name {
    std::string operator()(const Minkowski&) const { return "minkowski"; }
    std::string operator()(const Kerr&) const { return "kerr"; }
    std::string operator()(const Dihole&) const { return "dihole"; }
  };
  return std::visit(Name{}, s);
}

std::string describe(const Spacetime& s, bool exact) {
  auto num = [exact](double v) { return exact ? fmt::format("{:a}", v) : fmt::format("{:g}", v); };
  struct Describe {
    decltype(num)& n;
    std::string operator()(const Minkowski&) const { return "minkowski()"; }
    std::string operator()(const Kerr& k) const {
      return "kerr(mass=" + n(k.mass()) + ", spin=" + n(k.spin()) + ")";
    }
    std::string operator()(const Dihole& d) const {
      return "dihole(m1=" + n(d.mass1()) + ", m2=" + n(d.mass2()) + ", d=" + n(d.separation()) + ")";
    }
  };
  return std::visit(Describe{num}, s);
}

}  // namespace lc
