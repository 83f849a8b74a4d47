#include "stages/memo_budget.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "render/sample_memo.hpp"

namespace lc::farm {

std::optional<std::string> memo_refusal(const RenderSettings& rs, int sharers) {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page <= 0) return std::nullopt;  // unknown: trust the user
  const double budget = 0.25 * static_cast<double>(pages) * static_cast<double>(page) / std::max(1, sharers);
  const double need = static_cast<double>(SampleMemo::bytes_for(rs));
  if (need <= budget) return std::nullopt;
  return fmt::format("not reusing samples between frames: at {}x{} with {}x{} samples it would keep {:.1f} GB, more "
                     "than a quarter of this machine's memory ({:.1f} GB); --no-reuse turns reuse off without this note",
                     rs.width, rs.height, rs.supersample, rs.supersample, need / 1e9, budget / 1e9);
}

namespace {

// The number in a file holding one (a cgroup's limit), or nullopt ("max",
// missing, unreadable).
std::optional<std::uint64_t> number_in(const std::string& file) {
  std::ifstream in(file);
  std::uint64_t v = 0;
  if (in >> v) return v;
  return std::nullopt;
}

// The memory limits of this process's cgroups, its own and its parents'
// (a container mounts its own at the root of /sys/fs/cgroup).
std::vector<std::uint64_t> cgroup_limits() {
  std::vector<std::uint64_t> out;
  std::ifstream in("/proc/self/cgroup");
  std::string line;
  while (std::getline(in, line)) {
    // "0::/path" (v2) or "4:memory:/path" (v1).
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    std::string path = line.substr(second + 1);
    const bool v2 = controllers.empty();
    if (!v2 && controllers != "memory") continue;
    const std::string root = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
    const std::string name = v2 ? "/memory.max" : "/memory.limit_in_bytes";
    for (;;) {
      if (const auto v = number_in(root + (path == "/" ? "" : path) + name)) out.push_back(*v);
      if (path.empty() || path == "/") break;
      const auto slash = path.rfind('/');
      path = slash == 0 || slash == std::string::npos ? "/" : path.substr(0, slash);
    }
  }
  return out;
}

// MemAvailable from /proc/meminfo, in bytes.
std::optional<std::uint64_t> mem_available() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("MemAvailable:", 0) == 0) {
      std::istringstream fields(line.substr(13));
      std::uint64_t kb = 0;
      if (fields >> kb) return kb * 1024;
    }
  return std::nullopt;
}

}  // namespace

std::optional<MemoryBound> memory_available() {
  std::optional<MemoryBound> out;
  auto consider = [&out](std::uint64_t bytes, const char* from) {
    if (!out || bytes < out->bytes) out = MemoryBound{bytes, from};
  };
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if (pages > 0 && page > 0) consider(static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page), "physical memory");
  if (const auto a = mem_available()) consider(*a, "MemAvailable");
  for (const std::uint64_t limit : cgroup_limits()) consider(limit, "the cgroup's memory limit");
  return out;
}

std::optional<std::string> frame_memory_refusal(const RenderSettings& rs, const MemoryBound& available) {
  const double pixels = static_cast<double>(rs.width) * static_cast<double>(rs.height);
  const double need = pixels * frame_peak_bytes_per_pixel;
  if (need <= static_cast<double>(available.bytes)) return std::nullopt;
  return fmt::format("frames of {}x{} need ~{:.1f} GB of memory at their peak ({:g} bytes a pixel: docs/performance.md), "
                     "but this process has {:.1f} GB ({}): render smaller frames (--size, --scale) or a part at a time "
                     "(--region), or on a machine with more memory",
                     rs.width, rs.height, need / 1e9, frame_peak_bytes_per_pixel,
                     static_cast<double>(available.bytes) / 1e9, available.from);
}

}  // namespace lc::farm
