#include "transport/rank_board.hpp"

#include <algorithm>
#include <charconv>
#include <sstream>

#include <fmt/format.h>

namespace lc::farm {

void RankBoard::joined(int rank) {
  std::lock_guard lock(mutex_);
  held_[rank];
}

void RankBoard::handed(int rank, const std::vector<WorkItem>& items) {
  std::lock_guard lock(mutex_);
  auto& held = held_[rank];
  held.insert(held.end(), items.begin(), items.end());
}

void RankBoard::returned(int rank, const WorkItem& item) {
  std::lock_guard lock(mutex_);
  const auto it = held_.find(rank);
  if (it == held_.end()) return;
  auto& held = it->second;
  if (const auto pos = std::find(held.begin(), held.end(), item); pos != held.end()) held.erase(pos);
}

std::vector<RankHolding> RankBoard::holdings() const {
  std::lock_guard lock(mutex_);
  std::vector<RankHolding> out;
  for (const auto& [rank, held] : held_) {
    RankHolding h{rank, static_cast<int>(held.size()), {}};
    for (const WorkItem& item : held) h.frames.push_back(item.frame);
    std::sort(h.frames.begin(), h.frames.end());
    h.frames.erase(std::unique(h.frames.begin(), h.frames.end()), h.frames.end());
    out.push_back(std::move(h));
  }
  return out;
}

}  // namespace lc::farm
