// The farm's event log (telemetry/event_log.hpp): lines round-trip with their
// fields (a message's spaces and newlines too), a line cut short or
// garbled is skipped, and a reader keeps the latest run only, in bounded
// memory.

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "telemetry/event_log.hpp"
#include "scratch_dir.hpp"

namespace lc::farm {
namespace {

TEST(EventLog, EventsRoundTripAndTheLatestRunIsKept) {
  test::ScratchDir dir;
  {
    EventLog log(dir.path(), "shot");
    log.run_started({.pid = 1, .host = "old", .ranks = 1, .threads = 2, .todo = 3});
    log.frame_stored(0, 1.5, 100);
    log.run_ended("interrupted", 1);
    log.run_started({.pid = 42, .host = "node 7", .ranks = 3, .threads = 0, .todo = 5, .done_before = 1,
                     .width = 64, .height = 36});
    log.rank_joined(1, "n1", 4);
    log.rank_joined(2, "n2", 8);
    const std::vector<RankHolding> held{{1, 1, {2}}, {2, 0, {}}};
    log.progress(RunProgress{}, {2}, &held);
    log.frame_stored(1, 2.25, 2304);
    log.frame_stored(2, 2.5, 2304);
    log.error("frame 3: a script error\nat line 12 (100% sure)");
    log.rank_lost(2, "n2");
    log.run_ended("error", 2);
  }
  const EventSummary s = read_events(events_file(dir.path(), "shot"));
  ASSERT_TRUE(s.run);
  EXPECT_EQ(s.run->pid, 42);
  EXPECT_EQ(s.run->host, "node 7");
  EXPECT_EQ(s.run->ranks, 3);
  EXPECT_EQ(s.run->todo, 5);
  EXPECT_EQ(s.run->done_before, 1);
  EXPECT_EQ(s.run->width, 64);
  EXPECT_EQ(s.run->height, 36);
  ASSERT_EQ(s.ranks.size(), 2u);
  EXPECT_EQ(s.ranks[1].fields.at("host"), "n2");
  EXPECT_EQ(s.ranks[1].fields.at("threads"), "8");
  EXPECT_EQ(s.frames_stored, 2);
  ASSERT_TRUE(s.progress);
  EXPECT_EQ(s.progress->fields.at("held"), "1:1:2");
  EXPECT_EQ(s.lost, std::vector<int>{2});
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_EQ(s.errors[0].fields.at("message"), "frame 3: a script error\nat line 12 (100% sure)");
  ASSERT_TRUE(s.end);
  EXPECT_EQ(s.end->fields.at("status"), "error");
  EXPECT_EQ(s.recent.size(), 9u);  // the latest run's lines
  EXPECT_EQ(s.bad_lines, 0);
}

TEST(EventLog, CutAndGarbledLinesAreSkipped) {
  test::ScratchDir dir;
  {
    EventLog log(dir.path(), "shot");
    log.run_started({.pid = 7, .todo = 2});
    log.frame_stored(0, 1.0, 10);
  }
  const auto file = events_file(dir.path(), "shot");
  {
    std::ofstream out(file, std::ios::app);
    out << "t=1 event=frame frame=1 core_seconds=1 rays=1 #0000000000000000\n";  // a wrong check
    out << "t=2 event=frame frame=2";                                             // cut short
  }
  const EventSummary s = read_events(file);
  ASSERT_TRUE(s.run);
  EXPECT_EQ(s.frames_stored, 1);
  EXPECT_EQ(s.bad_lines, 1);
  // A missing file is an empty summary.
  EXPECT_FALSE(read_events(dir.path() / "none.events").run);
}

TEST(EventLog, OnlyALimitedTailIsHeld) {
  test::ScratchDir dir;
  {
    EventLog log(dir.path(), "shot");
    log.run_started({.todo = 100000});
    for (int f = 0; f < 100000; ++f) log.frame_stored(f, 0.5, 1);
  }
  const EventSummary s = read_events(events_file(dir.path(), "shot"), 50);
  EXPECT_EQ(s.frames_stored, 100000);
  ASSERT_EQ(s.recent.size(), 50u);
  EXPECT_EQ(s.recent.back().fields.at("frame"), "99999");
}

TEST(EventLog, ARunThatStoredNothingLeavesNoLogItMade) {
  test::ScratchDir dir;
  const auto file = events_file(dir.path(), "shot");
  {
    EventLog log(dir.path(), "shot");
    log.run_started({.todo = 3});
    log.error("frame 0: no static observer exists here");
    log.run_ended("error", 0);
  }
  EXPECT_FALSE(std::filesystem::exists(file));
  // A log kept from an earlier run stays, with this run's lines.
  {
    EventLog log(dir.path(), "shot");
    log.run_started({.todo = 1});
    log.frame_stored(0, 1.0, 1);
    log.run_ended("done", 1);
  }
  {
    EventLog log(dir.path(), "shot");
    log.run_started({.todo = 1});
    log.run_ended("error", 0);
  }
  const EventSummary s = read_events(file);
  ASSERT_TRUE(s.end);
  EXPECT_EQ(s.end->fields.at("status"), "error");
}

}  // namespace
}  // namespace lc::farm
