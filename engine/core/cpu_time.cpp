#include "core/cpu_time.hpp"

#include <cmath>
#include <ctime>
#include <fstream>

#include <sys/resource.h>

#include <fmt/format.h>

namespace lc {

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double process_cpu_seconds() {
  rusage u{};
  ::getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

std::optional<LoadAverage> load_average() {
  // The file's first three fields; anything else (a missing /proc, a field
  // that is not a finite number) gives nothing rather than a wrong figure.
  std::ifstream in("/proc/loadavg");
  LoadAverage l;
  if (!(in >> l.one >> l.five >> l.fifteen)) return std::nullopt;
  if (!std::isfinite(l.one) || !std::isfinite(l.five) || !std::isfinite(l.fifteen)) return std::nullopt;
  return l;
}

std::string describe_load(int cores) {
  const auto l = load_average();
  const std::string on = fmt::format("on {} core{}", cores, cores == 1 ? "" : "s");
  if (!l) return "load unknown (no /proc/loadavg) " + on;
  return fmt::format("load {:.2f} / {:.2f} / {:.2f} (1, 5, 15 min) {}", l->one, l->five, l->fifteen, on);
}

}  // namespace lc
