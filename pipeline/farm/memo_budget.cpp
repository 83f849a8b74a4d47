#include "farm/memo_budget.hpp"

#include <algorithm>

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

}  // namespace lc::farm
