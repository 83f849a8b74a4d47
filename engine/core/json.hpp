#pragma once
// Small JSON writers for the engine's reports (`lightcone inspect`): a
// number (null where JSON has none), a string, a scene position (polar
// ones with angles in degrees, as scripts write them), four components.

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "core/constants.hpp"
#include "core/fields.hpp"
#include "core/tensor.hpp"

namespace lc {

inline std::string json_number(double v) { return field_text(v, false); }
inline std::string json_string(const std::string& s) { return field_text(s, false); }

inline std::string json_position(const Vec4& p, bool polar) {
  const auto num = json_number;
  if (polar)
    return fmt::format("{{\"t\": {}, \"r\": {}, \"theta\": {}, \"phi\": {}}}", num(p[0]), num(p[1]), num(p[2] / degree),
                       num(p[3] / degree));
  return fmt::format("{{\"t\": {}, \"x\": {}, \"y\": {}, \"z\": {}}}", num(p[0]), num(p[1]), num(p[2]), num(p[3]));
}

inline std::string json_components(const Vec4& v) {
  return fmt::format("[{}, {}, {}, {}]", json_number(v[0]), json_number(v[1]), json_number(v[2]), json_number(v[3]));
}

}  // namespace lc
