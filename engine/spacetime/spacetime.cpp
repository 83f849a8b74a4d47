#include "spacetime/spacetime.hpp"

namespace lc {

std::string spacetime_name(const Spacetime& s) {
  struct Name {
    std::string operator()(const Minkowski&) const { return "minkowski"; }
    std::string operator()(const Kerr&) const { return "kerr"; }
    std::string operator()(const Dihole&) const { return "dihole"; }
  };
  return std::visit(Name{}, s);
}

}  // namespace lc
