#include "farm/local_farm.hpp"

#include <atomic>
#include <string>
#include <thread>
#include <vector>

#include "farm/threads.hpp"

namespace lc::farm {

void run_local_farm(WorkQueue& queue, FarmRun& run, StripeRenderer& renderer, int threads, Progress& progress) {
  std::atomic<int> running{threads};
  // The frames' record names this node, asked once: the threads are rank 0.
  const std::string node = host_name();
  auto work = [&] {
    while (auto item = queue.take_wait()) {
      try {
        const RenderStats stats = renderer.render(*item, queue.canvas(*item));
        run.finish(*item, stats, 0, node);
      } catch (const std::exception& e) {
        run.fail(e.what());
        break;
      }
    }
    running.fetch_sub(1);
  };
  std::vector<std::thread> pool;
  pool.reserve(threads);
  for (int k = 0; k < threads; ++k) pool.emplace_back(work);
  // Wake up for progress a few times a second; the threads need nothing
  // from this one.
  while (running.load() > 0) {
    run.wait(std::chrono::milliseconds(100));
    progress.tick(queue.progress());
  }
  for (auto& t : pool) t.join();
  // The writer may still be storing the last frames.
  while (!run.over()) {
    run.wait(std::chrono::milliseconds(100));
    progress.tick(queue.progress());
  }
}

}  // namespace lc::farm
