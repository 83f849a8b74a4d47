#include "schedule/farm_run.hpp"

namespace lc::farm {

FarmRun::FarmRun(WorkQueue& queue, FrameSink& sink, int writers, std::function<int()> signal_received)
    : queue_(queue), sink_(sink), signal_received_(std::move(signal_received)) {
  for (int k = 0; k < std::max(1, writers); ++k) writers_.emplace_back([this] { writer_loop(); });
}

FarmRun::~FarmRun() { close(); }

void FarmRun::finish(const WorkItem& item, const RenderStats& stats, int rank, std::string_view node) {
  auto done = queue_.finish(item, stats, rank, node);
  if (!done) return;
  {
    std::lock_guard lock(mutex_);
    pending_.push_back(std::move(*done));
  }
  changed_.notify_all();
}

void FarmRun::fail(const std::string& message) {
  {
    std::lock_guard lock(mutex_);
    if (!error_) error_ = message;
  }
  queue_.stop();
  changed_.notify_all();
}

std::optional<std::string> FarmRun::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void FarmRun::interrupt(int signal) {
  {
    std::lock_guard lock(mutex_);
    if (interrupted_ == 0) interrupted_ = signal;
  }
  queue_.stop();
  changed_.notify_all();
}

int FarmRun::interrupted() const {
  std::lock_guard lock(mutex_);
  return interrupted_;
}

void FarmRun::notice_signal() {
  if (!signal_received_) return;
  if (const int sig = signal_received_(); sig != 0) interrupt(sig);
}

bool FarmRun::over() {
  notice_signal();
  {
    std::lock_guard lock(mutex_);
    if (error_ || interrupted_) return true;
  }
  return queue_.all_stored();
}

void FarmRun::wait(std::chrono::milliseconds timeout) {
  {
    std::unique_lock lock(mutex_);
    changed_.wait_for(lock, timeout);
  }
  notice_signal();
}

// Each writer thread stores frames in completion order until closed and empty.  After its own
// failure (a full disk) it stores nothing more: the next write would fail
// alike, and the frames are rendered again on resume.
void FarmRun::writer_loop() {
  std::unique_lock lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return !pending_.empty() || closing_; });
    if (pending_.empty()) return;
    CompletedFrame frame = std::move(pending_.front());
    pending_.pop_front();
    if (writer_failed_) continue;
    lock.unlock();
    std::optional<std::string> failure;
    try {
      sink_.store(frame);
      queue_.stored(frame.pass, frame.frame);
    } catch (const std::exception& e) {
      failure = e.what();
    }
    lock.lock();
    if (failure) {
      writer_failed_ = true;
      if (!error_) error_ = *failure;
      lock.unlock();
      queue_.stop();
      lock.lock();
    }
    changed_.notify_all();
  }
}

void FarmRun::close() {
  {
    std::lock_guard lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  for (auto& w : writers_)
    if (w.joinable()) w.join();
}

}  // namespace lc::farm
