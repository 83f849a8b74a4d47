#include "cli/progress_printer.hpp"

#include <chrono>
#include <memory>

#include <fmt/format.h>

namespace lc {

ProgressFn progress_printer(const InterruptGuard& guard, std::string prefix, std::string unit) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  auto last = std::make_shared<Clock::time_point>(start);
  return [&guard, prefix = std::move(prefix), unit = std::move(unit), start, last](int done, int total) {
    guard.check();
    const Clock::time_point now = Clock::now();
    if (now - *last < std::chrono::seconds(1) || done == total) return;
    *last = now;
    const double s = std::chrono::duration<double>(now - start).count();
    fmt::print(stderr, "{}: {}/{} {}, {:.1f} {}/s\n", prefix, done, total, unit, done / s, unit);
  };
}

}  // namespace lc
