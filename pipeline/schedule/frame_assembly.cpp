#include "schedule/frame_assembly.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace lc::farm {

namespace {

// The journal's record of who rendered a frame (rank -> node and sets):
// every rank, or the max_listed_ranks that rendered the most sets (the
// lower rank on a tie), ascending by rank.
FrameMakers makers_of(const std::map<int, std::pair<std::string, int>>& by) {
  std::vector<std::pair<int, int>> most;  // (sets, rank)
  for (const auto& [rank, held] : by) most.emplace_back(held.second, rank);
  std::stable_sort(most.begin(), most.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  if (most.size() > max_listed_ranks) most.resize(max_listed_ranks);
  std::sort(most.begin(), most.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  FrameMakers m;
  m.count = static_cast<int>(by.size());
  for (const auto& [sets, rank] : most) m.ranks.push_back({rank, by.at(rank).first});
  return m;
}

}  // namespace

FrameAssembly::FrameAssembly(RenderSettings rs, const StripeLayout& layout, int frames,
                             const std::vector<int>& preview_stripes)
    : rs_(rs), layout_(layout) {
  const long n = frames;
  progress_.frames_total = frames;
  progress_.rows_total = n * layout_.height();
  if (!preview_stripes.empty()) {
    progress_.previews_total = frames;
    for (int s : preview_stripes) progress_.rows_total += n * layout_.row_count(s);
  }
}

void FrameAssembly::open(Pass pass, int frame, int stripes) {
  OpenFrame& of = open_[key(pass, frame)];
  of.canvas = std::make_unique<FrameImage>(make_frame(rs_));
  of.done.assign(static_cast<std::size_t>(stripes), 0);
  of.remaining = stripes;
  of.opened = std::chrono::steady_clock::now();
}

FrameImage& FrameAssembly::canvas(Pass pass, int frame) {
  auto it = open_.find(key(pass, frame));
  if (it == open_.end() || !it->second.canvas)
    throw std::logic_error(fmt::format("work queue: frame {} has no canvas", frame));
  return *it->second.canvas;
}

std::optional<CompletedFrame> FrameAssembly::finish(const WorkItem& item, int index, const RenderStats& stats,
                                                    int rank, std::string_view node) {
  auto it = open_.find(key(item.pass, item.frame));
  if (it == open_.end() || !it->second.canvas || index < 0 || it->second.done[static_cast<std::size_t>(index)])
    throw std::logic_error(
        fmt::format("work queue: stripe {} of frame {} was not handed out (or came back twice)", item.stripe, item.frame));
  OpenFrame& of = it->second;
  of.done[static_cast<std::size_t>(index)] = 1;
  of.stats += stats;
  auto [maker, first_set] = of.by.try_emplace(rank);
  if (first_set) maker->second.first = node;  // a rank's node is copied once a frame, not once a set
  ++maker->second.second;
  progress_.stats += stats;
  progress_.rows_done += layout_.row_count(item.stripe);
  if (--of.remaining > 0) return std::nullopt;
  CompletedFrame done{item.pass, item.frame, std::move(*of.canvas), of.stats, makers_of(of.by), of.opened};
  of.canvas.reset();  // the slot stays taken until stored()
  return done;
}

void FrameAssembly::stored(Pass pass, int frame) {
  auto it = open_.find(key(pass, frame));
  if (it == open_.end() || it->second.remaining != 0)
    throw std::logic_error(fmt::format("work queue: frame {} stored before it was complete", frame));
  open_.erase(it);
  if (pass == Pass::full)
    ++progress_.frames_stored;
  else
    ++progress_.previews_stored;
}

std::vector<int> FrameAssembly::open_frames() const {
  std::vector<int> out;
  for (const auto& [k, open] : open_)
    if (k.first == static_cast<int>(Pass::full)) out.push_back(k.second);
  return out;
}

}  // namespace lc::farm
