#include "schedule/work_queue.hpp"

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

WorkQueue::WorkQueue(RenderSettings rs, StripeLayout layout, std::vector<int> frames, Options options)
    : rs_(rs), layout_(layout), frames_(std::move(frames)), options_(options), owner_(layout_.stripes(), -1) {
  if (options_.max_open_frames < 1) options_.max_open_frames = 1;
  for (int s = 0; s < layout_.stripes(); ++s) {
    all_stripes_.push_back(s);
    if (options_.preview_every >= 2 && StripeLayout::in_preview(s, options_.preview_every)) preview_stripes_.push_back(s);
  }
  if (preview_stripes_.empty()) cur_pass_ = 1;  // no preview pass
  const long n = static_cast<long>(frames_.size());
  progress_.frames_total = static_cast<int>(n);
  progress_.rows_total = n * layout_.height();
  if (!preview_stripes_.empty()) {
    progress_.previews_total = static_cast<int>(n);
    for (int s : preview_stripes_) progress_.rows_total += n * layout_.row_count(s);
  }
}

std::size_t WorkQueue::pick_locked(int taker) {
  // Pops the first index of `list` not yet handed out (lists are kept
  // descending, so that is the back).
  auto from = [&](std::vector<std::size_t>& list) -> std::optional<std::size_t> {
    while (!list.empty() && handed_[list.back()]) list.pop_back();
    if (list.empty()) return std::nullopt;
    const std::size_t i = list.back();
    list.pop_back();
    return i;
  };
  if (taker >= 0) {
    if (auto i = from(left_for_[taker])) return *i;
    if (auto i = from(left_for_[-1])) return *i;
  }
  while (handed_[lowest_]) ++lowest_;
  return lowest_;
}

// Hands out a set of the frame under the cursor (pick_locked), opening the
// frame if needed, and moves the cursor on once the frame's last set is
// out (to the next pass after a pass's last frame, so drained() is true as
// soon as the last set is out); nullopt at the end, when stopped, or when
// opening a frame would exceed the limit.
std::optional<WorkItem> WorkQueue::take_locked(int taker) {
  if (stopped_ || cur_pass_ > 1 || frames_.empty()) return std::nullopt;
  const auto& stripes = cur_pass_ == 0 ? preview_stripes_ : all_stripes_;
  const Pass pass = cur_pass_ == 0 ? Pass::preview : Pass::full;
  const int frame = frames_[cur_frame_];
  if (!frame_started_) {
    // First set of a frame: it needs a canvas and a slot.
    if (static_cast<int>(open_.size()) >= options_.max_open_frames) return std::nullopt;
    OpenFrame& of = open_[key(pass, frame)];
    of.canvas = std::make_unique<FrameImage>(make_frame(rs_));
    of.done.assign(stripes.size(), 0);
    of.remaining = static_cast<int>(stripes.size());
    of.opened = std::chrono::steady_clock::now();
    frame_started_ = true;
    handed_.assign(stripes.size(), 0);
    handed_count_ = lowest_ = 0;
    left_for_.clear();
    for (std::size_t i = stripes.size(); i-- > 0;) left_for_[owner_[stripes[i]]].push_back(i);
  }
  const std::size_t index = pick_locked(taker);
  handed_[index] = 1;
  ++handed_count_;
  if (taker >= 0) owner_[stripes[index]] = taker;
  WorkItem item{frame, stripes[index], pass};
  if (handed_count_ == stripes.size()) {
    frame_started_ = false;
    if (++cur_frame_ == frames_.size()) {
      cur_frame_ = 0;
      ++cur_pass_;
    }
  }
  return item;
}

std::optional<WorkItem> WorkQueue::take() {
  std::lock_guard lock(mutex_);
  return take_locked(-1);
}

std::optional<WorkItem> WorkQueue::take_for(int taker) {
  std::lock_guard lock(mutex_);
  return take_locked(std::max(taker, 0));
}

std::optional<WorkItem> WorkQueue::take_wait() {
  std::unique_lock lock(mutex_);
  for (;;) {
    if (auto item = take_locked(-1)) return item;
    if (stopped_ || cur_pass_ > 1 || frames_.empty()) return std::nullopt;
    slot_freed_.wait(lock);
  }
}

bool WorkQueue::drained() const {
  std::lock_guard lock(mutex_);
  return cur_pass_ > 1 || frames_.empty();
}

FrameImage& WorkQueue::canvas(const WorkItem& item) {
  std::lock_guard lock(mutex_);
  auto it = open_.find(key(item.pass, item.frame));
  if (it == open_.end() || !it->second.canvas)
    throw std::logic_error(fmt::format("work queue: frame {} has no canvas", item.frame));
  return *it->second.canvas;
}

// Index of `stripe` in the pass's stripe list (preview stripes are every
// k-th, so the index is stripe / k).
std::optional<CompletedFrame> WorkQueue::finish(const WorkItem& item, const RenderStats& stats, int rank,
                                                std::string_view node) {
  std::lock_guard lock(mutex_);
  auto it = open_.find(key(item.pass, item.frame));
  const int index = item.pass == Pass::preview ? item.stripe / std::max(1, options_.preview_every) : item.stripe;
  const auto& stripes = stripes_of(item.pass);
  if (it == open_.end() || !it->second.canvas || index < 0 || index >= static_cast<int>(stripes.size()) ||
      stripes[index] != item.stripe || it->second.done[index])
    throw std::logic_error(
        fmt::format("work queue: stripe {} of frame {} was not handed out (or came back twice)", item.stripe, item.frame));
  OpenFrame& of = it->second;
  of.done[index] = 1;
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

void WorkQueue::stored(Pass pass, int frame) {
  {
    std::lock_guard lock(mutex_);
    auto it = open_.find(key(pass, frame));
    if (it == open_.end() || it->second.remaining != 0)
      throw std::logic_error(fmt::format("work queue: frame {} stored before it was complete", frame));
    open_.erase(it);
    if (pass == Pass::full)
      ++progress_.frames_stored;
    else
      ++progress_.previews_stored;
  }
  slot_freed_.notify_all();
}

bool WorkQueue::all_stored() const {
  std::lock_guard lock(mutex_);
  return (cur_pass_ > 1 || frames_.empty()) && open_.empty();
}

void WorkQueue::set_max_open_frames(int n) {
  {
    std::lock_guard lock(mutex_);
    options_.max_open_frames = std::max(1, n);
  }
  slot_freed_.notify_all();
}

void WorkQueue::stop() {
  {
    std::lock_guard lock(mutex_);
    stopped_ = true;
  }
  slot_freed_.notify_all();
}

bool WorkQueue::stopped() const {
  std::lock_guard lock(mutex_);
  return stopped_;
}

RunProgress WorkQueue::progress() const {
  std::lock_guard lock(mutex_);
  return progress_;
}

std::vector<int> WorkQueue::open_frames() const {
  std::lock_guard lock(mutex_);
  std::vector<int> out;
  for (const auto& [k, open] : open_)
    if (k.first == static_cast<int>(Pass::full)) out.push_back(k.second);
  return out;
}

int open_frames_for(int threads, int stripes) {
  stripes = std::max(1, stripes);
  return std::max(4, 2 * ((2 * threads + stripes - 1) / stripes) + 2);
}

}  // namespace lc::farm
