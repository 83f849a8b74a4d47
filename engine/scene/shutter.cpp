#include "scene/shutter.hpp"

#include <fmt/format.h>

namespace lc {

std::string Shutter::describe() const {
  if (closed()) return "shutter closed";
  return fmt::format("shutter {:g} ({}, {} instant{})", open, choice_name(position), time_samples,
                     time_samples == 1 ? "" : "s");
}

}  // namespace lc
