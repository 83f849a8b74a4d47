#pragma once
// The memory that the monitor's answers built in memory (JSON, a layer's
// picture, a pixel's trace) may hold at once, for the whole server
// (docs/monitor.md, "Safe by default").  A client that never reads keeps
// its answer held until libmicrohttpd gives up on it; so each body built
// takes its size from here until its response is freed, and one that
// would go past the bound is not held at all (the server answers 503).
// Files are not counted: they are sent from disk as the client reads.

#include <atomic>
#include <cstddef>

namespace lc::monitor {

class ReplyBudget {
 public:
  // `capacity`: the bytes all the bodies held at once may add up to.
  explicit ReplyBudget(std::size_t capacity) : capacity_(capacity) {}
  ReplyBudget(const ReplyBudget&) = delete;
  ReplyBudget& operator=(const ReplyBudget&) = delete;

  // Takes `bytes` for a body built; false, taking nothing, when the bodies
  // held would then add up to more than the capacity.  Safe from several
  // threads at once.
  bool take(std::size_t bytes);
  // Gives back `bytes` taken (the body freed).
  void give(std::size_t bytes);

  std::size_t capacity() const { return capacity_; }
  // The bytes taken and not given back.
  std::size_t held() const { return held_.load(); }

 private:
  const std::size_t capacity_;
  std::atomic<std::size_t> held_{0};
};

}  // namespace lc::monitor
