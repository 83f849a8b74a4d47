#include "schedule/hand_out.hpp"

#include <algorithm>

namespace lc::farm {

HandOut::HandOut(const StripeLayout& layout, std::vector<int> frames, int preview_every)
    : layout_(layout), frames_(std::move(frames)), preview_every_(preview_every), owner_(layout_.stripes(), -1) {
  for (int s = 0; s < layout_.stripes(); ++s) {
    all_stripes_.push_back(s);
    if (preview_every_ >= 2 && StripeLayout::in_preview(s, preview_every_)) preview_stripes_.push_back(s);
  }
  if (preview_stripes_.empty()) pass_ = 1;  // no preview pass
}

std::size_t HandOut::pick(int taker) {
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

// Moves the cursor on once the frame's last set is out (to the next pass
// after a pass's last frame, so drained() is true as soon as the last set
// is out).
std::optional<HandOut::Next> HandOut::next(int taker, bool may_open) {
  if (drained()) return std::nullopt;
  const auto& stripes = pass_ == 0 ? preview_stripes_ : all_stripes_;
  const Pass pass = pass_ == 0 ? Pass::preview : Pass::full;
  const int frame = frames_[frame_];
  const bool opens = !frame_started_;
  if (opens) {
    if (!may_open) return std::nullopt;
    frame_started_ = true;
    handed_.assign(stripes.size(), 0);
    handed_count_ = lowest_ = 0;
    left_for_.clear();
    for (std::size_t i = stripes.size(); i-- > 0;) left_for_[owner_[stripes[i]]].push_back(i);
  }
  const std::size_t index = pick(taker);
  handed_[index] = 1;
  ++handed_count_;
  if (taker >= 0) owner_[stripes[index]] = taker;
  const Next out{WorkItem{frame, stripes[index], pass}, opens};
  if (handed_count_ == stripes.size()) {
    frame_started_ = false;
    if (++frame_ == frames_.size()) {
      frame_ = 0;
      ++pass_;
    }
  }
  return out;
}

// Preview stripes are every k-th, so a preview stripe's index is stripe / k.
int HandOut::index_of(const WorkItem& item) const {
  const int index = item.pass == Pass::preview ? item.stripe / std::max(1, preview_every_) : item.stripe;
  const auto& stripes = stripes_of(item.pass);
  if (index < 0 || index >= static_cast<int>(stripes.size()) || stripes[index] != item.stripe) return -1;
  return index;
}

}  // namespace lc::farm
