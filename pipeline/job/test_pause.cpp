#include "job/test_pause.hpp"

#include <charconv>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

namespace lc::farm {

std::optional<long> test_pause_after() {
  const char* text = std::getenv(test_pause_variable);
  if (!text || !*text) return std::nullopt;
  const std::string_view v(text);
  long sets = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), sets);
  if (ec != std::errc() || end != v.data() + v.size() || sets < 0)
    throw std::invalid_argument(
        fmt::format("{}={}: expected a number of working sets (a test hook)", test_pause_variable, v));
  return sets;
}

}  // namespace lc::farm
