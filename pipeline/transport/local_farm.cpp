#include "transport/local_farm.hpp"

#include <algorithm>
#include <string>

#include "core/parallel_for.hpp"
#include "transport/threads.hpp"

namespace lc::farm {

void run_local_farm(WorkQueue& queue, FarmRun& run, StripeRenderer& renderer, int threads, Progress& progress) {
  // The frames' record names this node, asked once: the threads are rank 0.
  const std::string node = host_name();
  auto work = [&](std::size_t) {
    while (auto item = queue.take_wait()) {
      try {
        const RenderStats stats = renderer.render(*item, queue.canvas(*item));
        run.finish(*item, stats, 0, node);
      } catch (const std::exception& e) {
        run.fail(e.what());
        break;
      }
    }
  };
  // A worker a thread, each on the queue till it ends.  Wake up for progress
  // a few times a second; the threads need nothing from this one.
  const std::size_t workers = static_cast<std::size_t>(std::max(threads, 0));
  parallel_for(workers, {.threads = threads, .handout = Handout::by_thread}, work, [&](ParallelRun& pool) {
    while (pool.running()) {
      run.wait(std::chrono::milliseconds(100));
      progress.tick(queue.progress());
    }
  });
  // The writer may still be storing the last frames.
  while (!run.over()) {
    run.wait(std::chrono::milliseconds(100));
    progress.tick(queue.progress());
  }
}

}  // namespace lc::farm
