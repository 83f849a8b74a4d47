#include "schedule/work_queue.hpp"

#include <algorithm>

namespace lc::farm {

namespace {

// The options as the queue keeps them: at least one open frame.
WorkQueue::Options checked(WorkQueue::Options o) {
  o.max_open_frames = std::max(1, o.max_open_frames);
  return o;
}

}  // namespace

WorkQueue::WorkQueue(RenderSettings rs, StripeLayout layout, std::vector<int> frames, Options options)
    : options_(checked(options)),
      hand_out_(layout, std::move(frames), options_.preview_every),
      assembly_(rs, layout, hand_out_.frame_count(), hand_out_.stripes_of(Pass::preview)) {}

std::optional<WorkItem> WorkQueue::take_locked(int taker) {
  if (stopped_) return std::nullopt;
  const auto next = hand_out_.next(taker, assembly_.open_count() < options_.max_open_frames);
  if (!next) return std::nullopt;
  if (next->opens)
    assembly_.open(next->item.pass, next->item.frame, static_cast<int>(hand_out_.stripes_of(next->item.pass).size()));
  return next->item;
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
    if (stopped_ || hand_out_.drained()) return std::nullopt;
    slot_freed_.wait(lock);
  }
}

bool WorkQueue::drained() const {
  std::lock_guard lock(mutex_);
  return hand_out_.drained();
}

FrameImage& WorkQueue::canvas(const WorkItem& item) {
  std::lock_guard lock(mutex_);
  return assembly_.canvas(item.pass, item.frame);
}

std::optional<CompletedFrame> WorkQueue::finish(const WorkItem& item, const RenderStats& stats, int rank,
                                                std::string_view node) {
  std::lock_guard lock(mutex_);
  return assembly_.finish(item, hand_out_.index_of(item), stats, rank, node);
}

void WorkQueue::stored(Pass pass, int frame) {
  {
    std::lock_guard lock(mutex_);
    assembly_.stored(pass, frame);
  }
  slot_freed_.notify_all();
}

bool WorkQueue::all_stored() const {
  std::lock_guard lock(mutex_);
  return hand_out_.drained() && assembly_.open_count() == 0;
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
  return assembly_.progress();
}

std::vector<int> WorkQueue::open_frames() const {
  std::lock_guard lock(mutex_);
  return assembly_.open_frames();
}

int open_frames_for(int threads, int stripes) {
  stripes = std::max(1, stripes);
  return std::max(4, 2 * ((2 * threads + stripes - 1) / stripes) + 2);
}

}  // namespace lc::farm
