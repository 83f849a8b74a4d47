#pragma once
// The star pass's threads (stars/star_pass.hpp): independent pieces of work
// handed out one at a time, the CPU time of the helper threads counted.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

#include "core/cpu_time.hpp"

namespace lc {

// Runs fn(k) for every k in [0, count) once, on up to `threads` threads
// (this one among them) in no particular order; adds the CPU time the
// threads it started spent to `helpers_cpu` (this thread's own is the
// caller's to measure).  The first exception thrown is rethrown once all
// stop.
template <class F>
void for_each_parallel(std::size_t count, int threads, F&& fn, double& helpers_cpu) {
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::exception_ptr error;
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1)) < count;) {
      try {
        fn(k);
      } catch (...) {
        std::lock_guard lock(mutex);
        if (!error) error = std::current_exception();
        next = count;
      }
    }
  };
  const std::size_t helpers = count == 0 ? 0 : std::min(count, static_cast<std::size_t>(std::max(1, threads))) - 1;
  std::vector<std::thread> pool;
  pool.reserve(helpers);
  for (std::size_t t = 0; t < helpers; ++t)
    pool.emplace_back([&] {
      const double start = thread_cpu_seconds();
      work();
      std::lock_guard lock(mutex);
      helpers_cpu += thread_cpu_seconds() - start;
    });
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace lc
