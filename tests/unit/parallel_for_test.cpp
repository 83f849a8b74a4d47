// parallel_for (core/parallel_for.hpp), the pool every threaded part uses:
// each index once, the caller's share of the work, the two hand-outs, the
// first exception carried to the caller, stopping, and the watch.

#include "core/parallel_for.hpp"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace lc {
namespace {

// Counts, per index, how often fn ran it.
std::vector<int> runs_of(std::size_t count, const ParallelFor& how) {
  std::vector<std::atomic<int>> runs(count);
  parallel_for(count, how, [&](std::size_t k) { runs[k].fetch_add(1); });
  return std::vector<int>(runs.begin(), runs.end());
}

TEST(ParallelFor, RunsEveryIndexOnceForEveryHandoutAndThreadCount) {
  for (Handout handout : {Handout::next_free, Handout::by_thread})
    for (int threads : {-1, 0, 1, 2, 3, 8})
      for (std::size_t count : {0u, 1u, 2u, 7u, 1000u}) {
        const std::vector<int> runs = runs_of(count, {.threads = threads, .handout = handout});
        EXPECT_EQ(runs, std::vector<int>(count, 1)) << threads << " threads, " << count << " indices";
      }
}

TEST(ParallelFor, WorkersAreAtLeastOneAndNoMoreThanTheIndices) {
  EXPECT_EQ(parallel_workers(0, 4), 0u);
  EXPECT_EQ(parallel_workers(3, 8), 3u);
  EXPECT_EQ(parallel_workers(100, 4), 4u);
  EXPECT_EQ(parallel_workers(100, 0), 1u);
  EXPECT_EQ(parallel_workers(100, -3), 1u);
}

TEST(ParallelFor, OneThreadRunsEverythingInlineInOrder) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::size_t> order;
  bool elsewhere = false;
  parallel_for(5, {.threads = 1}, [&](std::size_t k, std::size_t worker) {
    order.push_back(k);
    elsewhere = elsewhere || std::this_thread::get_id() != caller || worker != 0;
  });
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_FALSE(elsewhere);
}

TEST(ParallelFor, TheCallerIsWorkerZeroAndEachWorkerHasOneThread) {
  const std::thread::id caller = std::this_thread::get_id();
  std::mutex mutex;
  std::vector<std::set<std::thread::id>> threads_of(parallel_workers(400, 3));
  parallel_for(400, {.threads = 3}, [&](std::size_t, std::size_t worker) {
    {
      std::lock_guard lock(mutex);
      threads_of.at(worker).insert(std::this_thread::get_id());
    }
    // Long enough that the caller, last to begin, still finds indices left.
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  });
  ASSERT_EQ(threads_of.size(), 3u);
  EXPECT_EQ(threads_of[0], std::set<std::thread::id>{caller});
  std::set<std::thread::id> all;
  for (const auto& t : threads_of) {
    EXPECT_LE(t.size(), 1u);
    all.insert(t.begin(), t.end());
  }
  EXPECT_EQ(all.size(), [&] {
    std::size_t used = 0;
    for (const auto& t : threads_of) used += t.size();
    return used;
  }());
}

// Each of `threads` indices waits until all have begun: only a hand-out that
// gives every index a thread of its own at once gets through.
TEST(ParallelFor, ByThreadGivesEachIndexItsOwnThreadAtOnce) {
  constexpr int threads = 4;
  std::mutex mutex;
  std::condition_variable all_in;
  int in = 0;
  std::atomic<int> met{0};
  std::set<std::size_t> workers;
  parallel_for(threads, {.threads = threads, .handout = Handout::by_thread}, [&](std::size_t k, std::size_t worker) {
    std::unique_lock lock(mutex);
    workers.insert(worker);
    EXPECT_EQ(k, worker);
    ++in;
    all_in.notify_all();
    if (all_in.wait_for(lock, std::chrono::seconds(5), [&] { return in == threads; })) ++met;
  });
  EXPECT_EQ(met.load(), threads);
  EXPECT_EQ(workers.size(), static_cast<std::size_t>(threads));
}

TEST(ParallelFor, ByThreadStridesTheIndices) {
  std::mutex mutex;
  std::vector<std::vector<std::size_t>> of(3);
  parallel_for(8, {.threads = 3, .handout = Handout::by_thread}, [&](std::size_t k, std::size_t worker) {
    std::lock_guard lock(mutex);
    of[worker].push_back(k);
  });
  EXPECT_EQ(of[0], (std::vector<std::size_t>{0, 3, 6}));
  EXPECT_EQ(of[1], (std::vector<std::size_t>{1, 4, 7}));
  EXPECT_EQ(of[2], (std::vector<std::size_t>{2, 5}));
}

TEST(ParallelFor, AnExceptionReachesTheCallerAndStopsTheHandout) {
  std::atomic<int> ran{0};
  try {
    parallel_for(100, {.threads = 1}, [&](std::size_t k) {
      ++ran;
      if (k == 3) throw std::invalid_argument("index 3");
    });
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "index 3");
  }
  EXPECT_EQ(ran.load(), 4);
}

TEST(ParallelFor, AHelperThreadsExceptionReachesTheCallerAfterAllReturn) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> active{0};
  try {
    // Indices 1 to 3 are the helpers' (by_thread), so the throw is theirs.
    parallel_for(4, {.threads = 4, .handout = Handout::by_thread}, [&](std::size_t k) {
      ++active;
      std::this_thread::sleep_for(std::chrono::milliseconds(k == 0 ? 0 : 20));
      --active;
      if (std::this_thread::get_id() != caller) throw std::runtime_error("helper");
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "helper");
    // Every thread had returned before the caller heard.
    EXPECT_EQ(active.load(), 0);
  }
}

TEST(ParallelFor, HelpersCpuTimeIsAdded) {
  double cpu = 0.0;
  std::atomic<long> sink{0};
  parallel_for(2, {.threads = 2, .handout = Handout::by_thread, .helpers_cpu = &cpu}, [&](std::size_t) {
    const double until = thread_cpu_seconds() + 0.02;
    long n = 0;
    while (thread_cpu_seconds() < until) ++n;
    sink += n;
  });
  // The caller's own share is not counted: one helper's 20 ms.
  EXPECT_GE(cpu, 0.02);
  EXPECT_LT(cpu, 0.04 + 0.02);
}

TEST(ParallelFor, AWatchRunsOnTheCallerWhileEveryIndexRunsElsewhere) {
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<int> on_caller{0}, ran{0};
  bool watched = false, saw_end = false;
  parallel_for(
      50, {.threads = 2},
      [&](std::size_t) {
        ++ran;
        if (std::this_thread::get_id() == caller) ++on_caller;
      },
      [&](ParallelRun& run) {
        watched = std::this_thread::get_id() == caller;
        while (run.running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        saw_end = ran.load() == 50 && !run.stopped();
      });
  EXPECT_TRUE(watched);
  EXPECT_TRUE(saw_end);
  EXPECT_EQ(on_caller.load(), 0);
}

TEST(ParallelFor, AWatchRunsWhenThereIsNoIndex) {
  bool watched = false, running = true;
  parallel_for(0, {.threads = 4}, [](std::size_t) { FAIL(); },
               [&](ParallelRun& run) {
                 watched = true;
                 running = run.running();
               });
  EXPECT_TRUE(watched);
  EXPECT_FALSE(running);
}

TEST(ParallelFor, TheWatchStopsTheHandoutAndTheOnesBegunFinish) {
  std::atomic<bool> release{false};
  std::atomic<int> begun{0}, finished{0};
  parallel_for(
      1000, {.threads = 2},
      [&](std::size_t) {
        ++begun;
        while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        ++finished;
      },
      [&](ParallelRun& run) {
        while (begun < 2) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        run.stop();
        EXPECT_TRUE(run.stopped());
        release = true;
      });
  EXPECT_EQ(begun.load(), 2);
  EXPECT_EQ(finished.load(), 2);
}

TEST(ParallelFor, AWorkersExceptionShowsAsStoppedToTheWatchAndReachesTheCaller) {
  bool stopped = false;
  EXPECT_THROW(parallel_for(
                   10, {.threads = 2, .handout = Handout::by_thread},
                   [](std::size_t k) {
                     if (k == 5) throw std::out_of_range("frame 5");
                   },
                   [&](ParallelRun& run) {
                     while (!run.stopped()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                     stopped = true;
                   }),
               std::out_of_range);
  EXPECT_TRUE(stopped);
}

TEST(ParallelFor, TheWatchsExceptionStopsTheWorkersAndReachesTheCaller) {
  std::atomic<int> ran{0};
  EXPECT_THROW(parallel_for(
                   100000, {.threads = 2},
                   [&](std::size_t) {
                     ++ran;
                     std::this_thread::sleep_for(std::chrono::microseconds(100));
                   },
                   [&](ParallelRun&) {
                     while (ran < 10) std::this_thread::sleep_for(std::chrono::milliseconds(1));
                     throw std::runtime_error("interrupted");
                   }),
               std::runtime_error);
  EXPECT_LT(ran.load(), 100000);
}

}  // namespace
}  // namespace lc
