// The work queue (schedule/work_queue.hpp), the joint of the hand-out and
// the frame assembly: every working set is handed out exactly once, frames
// complete when their last stripe arrives, previews come first, the number
// of open frames is bounded, and threads sharing the queue agree.

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <thread>

#include <gtest/gtest.h>

#include "tiny_frame.hpp"

#include "schedule/farm_run.hpp"
#include "store/frame_store.hpp"
#include "schedule/work_queue.hpp"

namespace lc::farm {
namespace {

// Hands out everything single-threaded and checks each set appears once.
TEST(WorkQueue, EverySetOnceInFrameOrder) {
  WorkQueue q(test::settings_of_size(4, 10), StripeLayout(10, 5), {3, 7, 9}, {.preview_every = 0, .max_open_frames = 100});
  std::vector<WorkItem> items;
  while (auto i = q.take()) items.push_back(*i);
  EXPECT_TRUE(q.drained());
  ASSERT_EQ(items.size(), 15u);
  for (std::size_t k = 0; k < items.size(); ++k) {
    EXPECT_EQ(items[k].frame, std::vector<int>({3, 7, 9})[k / 5]);
    EXPECT_EQ(items[k].stripe, static_cast<int>(k % 5));
    EXPECT_EQ(items[k].pass, Pass::full);
  }
}

TEST(WorkQueue, WorkersGetBackTheStripesTheyHadBefore) {
  // Two MPI workers (ranks 1 and 2) asking in turns share frame 0; in frame
  // 1 each gets the stripes it had, whoever asks first and however often,
  // so its sample memo holds their rows.  What one leaves, the other takes.
  WorkQueue q(test::settings_of_size(4, 12), StripeLayout(12, 6), {0, 1, 2}, {.preview_every = 0, .max_open_frames = 100});
  std::map<int, std::set<int>> had;
  for (int k = 0; k < 6; ++k) {
    const int rank = 1 + k % 2;
    const auto item = q.take_for(rank);
    ASSERT_TRUE(item);
    EXPECT_EQ(item->frame, 0);
    had[rank].insert(item->stripe);
  }
  EXPECT_EQ(had[1], std::set<int>({0, 2, 4}));
  for (int k = 0; k < 3; ++k) {
    const auto item = q.take_for(2);
    EXPECT_EQ(item->frame, 1);
    EXPECT_TRUE(had[2].count(item->stripe)) << item->stripe;
  }
  // Rank 2 has had all of its own: it takes rank 1's, lowest first.
  EXPECT_EQ(q.take_for(2)->stripe, 0);
  for (int k = 0; k < 2; ++k) {
    const auto item = q.take_for(1);
    EXPECT_EQ(item->frame, 1);
    EXPECT_TRUE(had[1].count(item->stripe)) << item->stripe;
  }
  // Frame 2: stripe 0 went to rank 2 last.
  EXPECT_EQ(q.take_for(2)->stripe, 0);
  EXPECT_EQ(q.take_for(1)->stripe, 2);
  // Every set of every frame came out exactly once.
  int rest = 0;
  while (q.take_for(1)) ++rest;
  EXPECT_EQ(rest, 4);
  EXPECT_TRUE(q.drained());
}

TEST(WorkQueue, FrameCompletesWithItsLastStripeAndHoldsItsRows) {
  WorkQueue q(test::settings_of_size(3, 4), StripeLayout(4, 2), {0}, {});
  const auto a = *q.take(), b = *q.take();
  // Write each stripe's row numbers into its rows, in reverse order of hand-out.
  for (const auto& item : {b, a})
    for (int j : q.layout().rows(item.stripe))
      for (int i = 0; i < 3; ++i) q.canvas(item).rgb[3 * (j * 3 + i)] = static_cast<float>(j);
  EXPECT_FALSE(q.finish(b, {10, 0, 0}).has_value());
  const auto done = q.finish(a, {5, 0, 0});
  ASSERT_TRUE(done.has_value());
  EXPECT_EQ(done->frame, 0);
  EXPECT_EQ(done->stats.rays, 15);
  for (int j = 0; j < 4; ++j) EXPECT_EQ(done->image.rgb[3 * (j * 3)], static_cast<float>(j));
  EXPECT_FALSE(q.all_stored());
  q.stored(Pass::full, 0);
  EXPECT_TRUE(q.all_stored());
  EXPECT_EQ(q.progress().frames_stored, 1);
}

// A completed frame names the ranks whose sets made it, with their nodes,
// and when its first set was handed out (the journal's wall time starts
// there); of more ranks than are listed, those that rendered the most.
TEST(WorkQueue, AFrameNamesTheRanksThatRenderedItAndWhenItWasDispatched) {
  WorkQueue q(test::settings_of_size(2, 4), StripeLayout(4, 4), {0}, {});
  const auto before = std::chrono::steady_clock::now();
  const auto a = *q.take_for(2), b = *q.take_for(1), c = *q.take_for(2), d = *q.take_for(2);
  q.finish(a, {}, 2, "node-b");
  q.finish(b, {}, 1, "node-a");
  q.finish(c, {}, 2, "node-b");
  const auto done = q.finish(d, {}, 2, "node-b");
  ASSERT_TRUE(done.has_value());
  EXPECT_EQ(done->makers, (FrameMakers{{{1, "node-a"}, {2, "node-b"}}, 2}));
  EXPECT_GE(done->dispatched, before);
  EXPECT_LE(done->dispatched, std::chrono::steady_clock::now());

  const int ranks = static_cast<int>(max_listed_ranks) + 4;
  WorkQueue many(test::settings_of_size(2, 64), StripeLayout(64, 64), {0}, {});
  std::vector<WorkItem> items;
  while (auto i = many.take()) items.push_back(*i);
  ASSERT_EQ(items.size(), 64u);
  // Ranks 1..20: rank r renders one set, ranks 5..20 a second one too.
  std::vector<int> by;
  for (int r = 1; r <= ranks; ++r) by.push_back(r);
  for (int r = 5; r <= ranks; ++r) by.push_back(r);
  std::optional<CompletedFrame> last;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const int r = k < by.size() ? by[k] : ranks;
    last = many.finish(items[k], {}, r, "n" + std::to_string(r));
  }
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->makers.count, ranks);
  ASSERT_EQ(last->makers.ranks.size(), max_listed_ranks);
  EXPECT_EQ(last->makers.ranks.front(), (FrameMakers::Rank{5, "n5"}));  // 1..4 rendered the fewest
  EXPECT_EQ(last->makers.ranks.back(), (FrameMakers::Rank{ranks, "n" + std::to_string(ranks)}));
}

TEST(WorkQueue, DuplicateOrUnknownSetIsRefused) {
  WorkQueue q(test::settings_of_size(2, 4), StripeLayout(4, 2), {0}, {});
  const auto a = *q.take();
  q.finish(a, {});
  EXPECT_THROW(q.finish(a, {}), std::logic_error);
  EXPECT_THROW(q.finish({5, 0, Pass::full}, {}), std::logic_error);
}

TEST(WorkQueue, PreviewStripesOfEveryFrameComeFirst) {
  WorkQueue q(test::settings_of_size(2, 8), StripeLayout(8, 8), {0, 1}, {.preview_every = 4, .max_open_frames = 100});
  EXPECT_EQ(q.stripes_of(Pass::preview), (std::vector<int>{0, 4}));
  std::vector<WorkItem> items;
  while (auto i = q.take()) items.push_back(*i);
  ASSERT_EQ(items.size(), 2u * 2 + 2u * 8);
  EXPECT_EQ(items[0], (WorkItem{0, 0, Pass::preview}));
  EXPECT_EQ(items[1], (WorkItem{0, 4, Pass::preview}));
  EXPECT_EQ(items[2], (WorkItem{1, 0, Pass::preview}));
  EXPECT_EQ(items[3], (WorkItem{1, 4, Pass::preview}));
  EXPECT_EQ(items[4], (WorkItem{0, 0, Pass::full}));
  const RunProgress p = q.progress();
  EXPECT_EQ(p.rows_total, 2 * 2 + 2 * 8);
  EXPECT_EQ(p.previews_total, 2);
}

TEST(WorkQueue, OpenFramesAreBounded) {
  WorkQueue q(test::settings_of_size(2, 2), StripeLayout(2, 2), {0, 1, 2}, {.preview_every = 0, .max_open_frames = 2});
  std::vector<WorkItem> items;
  while (auto i = q.take()) items.push_back(*i);
  EXPECT_EQ(items.size(), 4u);  // frames 0 and 1; frame 2 waits for a slot
  EXPECT_FALSE(q.drained());
  q.finish(items[0], {});
  q.finish(items[1], {});
  EXPECT_FALSE(q.take().has_value());  // complete is not enough: stored frees the slot
  q.stored(Pass::full, 0);
  EXPECT_EQ(q.take()->frame, 2);
}

TEST(WorkQueue, StopEndsTakeWait) {
  WorkQueue q(test::settings_of_size(2, 2), StripeLayout(2, 1), {0, 1}, {.preview_every = 0, .max_open_frames = 1});
  ASSERT_TRUE(q.take().has_value());
  std::thread waiter([&] { EXPECT_FALSE(q.take_wait().has_value()); });
  q.stop();
  waiter.join();
}

// Completed frames go to a sink that records them.
class RecordingSink final : public FrameSink {
 public:
  void store(const CompletedFrame& f) override {
    std::lock_guard lock(mutex);
    frames.push_back(f.frame);
    images.push_back(f.image);
  }
  std::mutex mutex;
  std::vector<int> frames;
  std::vector<FrameImage> images;
};

// Four threads drain a queue through a FarmRun; every pixel is written by
// exactly one set, every frame stored once.
TEST(WorkQueue, ThreadsShareTheQueue) {
  const int W = 5, H = 23;
  WorkQueue q(test::settings_of_size(W, H), StripeLayout(H, 6), {0, 1, 2, 3, 4, 5, 6, 7}, {.preview_every = 3, .max_open_frames = 3});
  RecordingSink sink;
  {
    FarmRun run(q, sink);
    std::vector<std::thread> pool;
    for (int t = 0; t < 4; ++t)
      pool.emplace_back([&] {
        while (auto item = q.take_wait()) {
          FrameImage& c = q.canvas(*item);
          for (int j : q.layout().rows(item->stripe))
            for (int i = 0; i < W; ++i) c.rgb[3 * (j * W + i)] += 1.0f;
          run.finish(*item, {1, 0, 0});
        }
      });
    for (auto& t : pool) t.join();
    while (!run.over()) run.wait(std::chrono::milliseconds(10));
    run.close();
    EXPECT_FALSE(run.error().has_value());
  }
  EXPECT_EQ(sink.frames.size(), 16u);  // 8 previews + 8 frames
  std::multiset<int> frames(sink.frames.begin(), sink.frames.end());
  for (int f = 0; f < 8; ++f) EXPECT_EQ(frames.count(f), 2u);
  for (const auto& img : sink.images) {
    bool preview = false;
    for (int j = 0; j < H; ++j) {
      const float v = img.rgb[3 * (j * W)];
      EXPECT_TRUE(v == 0.0f || v == 1.0f);
      preview |= v == 0.0f;
    }
    if (!preview) {
      for (int p = 0; p < W * H; ++p) EXPECT_EQ(img.rgb[3 * p], 1.0f);
    }
  }
  EXPECT_EQ(q.progress().stats.rays, 8 * 2 + 8 * 6);
}

// A signal noticed by the run stops the queue but is no error: the frame
// completed before it is still stored, the one half done is not.
TEST(WorkQueue, AnInterruptedRunStoresWhatIsComplete) {
  WorkQueue q(test::settings_of_size(2, 4), StripeLayout(4, 2), {0, 1, 2}, {.preview_every = 0, .max_open_frames = 3});
  RecordingSink sink;
  int signal = 0;
  {
    FarmRun run(q, sink, 1, [&signal] { return signal; });
    for (int k = 0; k < 3; ++k) run.finish(*q.take(), {});  // frame 0 (two sets), half of frame 1
    EXPECT_FALSE(run.over());
    signal = 2;  // SIGINT arrives
    EXPECT_TRUE(run.over());
    EXPECT_EQ(run.interrupted(), 2);
    EXPECT_FALSE(q.take().has_value()) << "work handed out after the signal";
    const auto last = q.take_wait();
    EXPECT_FALSE(last.has_value());
    signal = 15;  // a second one does not replace the first
    run.wait(std::chrono::milliseconds(1));
    EXPECT_EQ(run.interrupted(), 2);
    run.close();
    EXPECT_FALSE(run.error().has_value());
  }
  EXPECT_EQ(sink.frames, (std::vector<int>{0}));
}

}  // namespace
}  // namespace lc::farm
