#pragma once
// The project's one pool of threads: rows of a frame, the star pass's tiles,
// a shot's frames to develop, the farm's render workers all run through
// parallel_for, so hand-out, stopping and errors behave the same everywhere.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

#include "core/cpu_time.hpp"

namespace lc {

// How the indices are shared among the threads.
enum class Handout {
  // A thread takes the next index nobody has taken (one atomic counter):
  // pieces of uneven cost even out.
  next_free,
  // Thread t takes t, t + n, t + 2n, ... of n threads: with as many indices
  // as threads, each index is a long-lived worker on a thread of its own.
  by_thread,
};

// How parallel_for runs.  threads <= 0 counts as 1: a pool's default (every
// core, say) is its caller's to choose.
struct ParallelFor {
  int threads = 1;
  Handout handout = Handout::next_free;
  // When given, the CPU seconds the threads parallel_for started spent are
  // added here (the calling thread's own are its caller's to measure).
  double* helpers_cpu = nullptr;
};

// The number of threads parallel_for runs for `count` indices: `threads`
// (at least 1) but no more than there are indices, so 0 for none.  A worker
// number passed to fn is below it, so per-worker state can be sized by it.
inline std::size_t parallel_workers(std::size_t count, int threads) {
  return std::min(count, static_cast<std::size_t>(std::max(1, threads)));
}

namespace parallel_detail {

// What the threads of one parallel_for call share.
struct Pool {
  std::size_t count = 0, workers = 0;
  Handout handout = Handout::next_free;
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> running{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::exception_ptr error;

  // Keeps the first error (later ones are what the first one caused, as a
  // rule) and stops the hand-out, so the caller hears of it soon.
  void fail(std::exception_ptr e) {
    std::lock_guard lock(mutex);
    if (!error) error = e;
    stop = true;
  }

  // Runs fn on the indices of worker `worker` until there are none or the
  // pool stops; an exception stops the pool rather than the program.
  template <class F>
  void work(F& fn, std::size_t worker) {
    auto one = [&](std::size_t k) {
      try {
        if constexpr (std::is_invocable_v<F&, std::size_t, std::size_t>)
          fn(k, worker);
        else
          fn(k);
      } catch (...) {
        fail(std::current_exception());
      }
    };
    if (handout == Handout::next_free) {
      for (std::size_t k; !stop.load(std::memory_order_relaxed) && (k = next.fetch_add(1)) < count;) one(k);
    } else {
      for (std::size_t k = worker; k < count && !stop.load(std::memory_order_relaxed); k += workers) one(k);
    }
  }
};

}  // namespace parallel_detail

// What a watch (below) sees of the pool it watches; lives as long as the call.
class ParallelRun {
 public:
  explicit ParallelRun(parallel_detail::Pool& pool) : pool_(pool) {}
  // Some worker has not returned yet.
  bool running() const { return pool_.running.load(std::memory_order_acquire) > 0; }
  // stop() was called or a worker threw.
  bool stopped() const { return pool_.stop.load(); }
  // No index is handed out from now on; the ones begun run to their end.
  void stop() { pool_.stop = true; }

 private:
  parallel_detail::Pool& pool_;
};

namespace parallel_detail {

// The watch of a parallel_for that has none: the caller works instead.
struct NoWatch {
  void operator()(ParallelRun&) const {}
};

// Runs the workers: the caller as worker 0 when W is NoWatch, otherwise all
// on new threads while the caller runs watch(run).  Joins them all
// before returning or throwing; rethrows the first exception of a worker or
// of the watch.
template <class F, class W>
void run(std::size_t count, const ParallelFor& how, F& fn, W& watch) {
  constexpr bool caller_works = std::is_same_v<W, NoWatch>;
  Pool pool;
  pool.count = count;
  pool.workers = parallel_workers(count, how.threads);
  pool.handout = how.handout;
  pool.running = pool.workers;
  const std::size_t first_started = caller_works ? std::min<std::size_t>(1, pool.workers) : 0;
  std::vector<std::thread> threads;
  threads.reserve(pool.workers - first_started);
  auto started = [&](std::size_t worker) {
    const double start = how.helpers_cpu ? thread_cpu_seconds() : 0.0;
    pool.work(fn, worker);
    if (how.helpers_cpu) {
      std::lock_guard lock(pool.mutex);
      *how.helpers_cpu += thread_cpu_seconds() - start;
    }
    pool.running.fetch_sub(1, std::memory_order_release);
  };
  try {
    for (std::size_t w = first_started; w < pool.workers; ++w) threads.emplace_back(started, w);
  } catch (...) {
    // No thread to be had: the ones started finish what they began.
    pool.fail(std::current_exception());
    pool.running.fetch_sub(pool.workers - first_started - threads.size(), std::memory_order_release);
  }
  if constexpr (caller_works) {
    if (pool.workers > 0) {
      pool.work(fn, 0);
      pool.running.fetch_sub(1, std::memory_order_release);
    }
  } else {
    ParallelRun view(pool);
    try {
      watch(view);
    } catch (...) {
      // Workers blocked on something of their own (a queue) must be woken
      // by its owner, or this join waits for them.
      pool.fail(std::current_exception());
    }
  }
  for (std::thread& t : threads) t.join();
  if (pool.error) std::rethrow_exception(pool.error);
}

}  // namespace parallel_detail

// Runs fn(k), or fn(k, worker) with worker below parallel_workers(count,
// threads), for every k in [0, count) once, on parallel_workers(count,
// threads) threads: the calling thread is worker 0, so one thread runs all
// inline.  The first exception stops the hand-out; it is rethrown once all
// have returned.  Order of the indices: none.
template <class F>
void parallel_for(std::size_t count, const ParallelFor& how, F&& fn) {
  parallel_detail::NoWatch none;
  parallel_detail::run(count, how, fn, none);
}

// As above, but every worker gets a thread of its own and the calling thread
// runs watch(ParallelRun&) meanwhile (progress, signals; run.stop() to stop
// the hand-out, run.running() to see the workers out) and joins the workers
// when the watch returns.  The watch runs even when there is no index.
template <class F, class W>
void parallel_for(std::size_t count, const ParallelFor& how, F&& fn, W&& watch) {
  parallel_detail::run(count, how, fn, watch);
}

}  // namespace lc
