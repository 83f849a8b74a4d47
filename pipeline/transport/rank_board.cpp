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

std::string format_holdings(const std::vector<RankHolding>& holdings, std::size_t max_chars, bool* complete) {
  std::string out;
  if (complete) *complete = true;
  for (const RankHolding& h : holdings) {
    if (h.sets == 0) continue;
    const std::string entry = fmt::format("{}{}:{}:{}", out.empty() ? "" : ",", h.rank, h.sets, fmt::join(h.frames, "+"));
    if (out.size() + entry.size() > max_chars) {
      if (complete) *complete = false;
      break;
    }
    out += entry;
  }
  return out;
}

namespace {

bool parse_int(const std::string& text, int& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

std::vector<RankHolding> parse_holdings(const std::string& text) {
  std::vector<RankHolding> out;
  std::istringstream entries(text);
  for (std::string entry; std::getline(entries, entry, ',');) {
    const auto a = entry.find(':'), b = entry.find(':', a == std::string::npos ? a : a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    RankHolding h;
    if (!parse_int(entry.substr(0, a), h.rank) || !parse_int(entry.substr(a + 1, b - a - 1), h.sets)) continue;
    std::istringstream frames(entry.substr(b + 1));
    bool ok = true;
    for (std::string f; ok && std::getline(frames, f, '+');) {
      int frame = 0;
      ok = parse_int(f, frame);
      h.frames.push_back(frame);
    }
    if (ok) out.push_back(std::move(h));
  }
  return out;
}

}  // namespace lc::farm
