// The monitor's API (monitor/monitor_api.hpp), without a socket: every
// endpoint answers from the journal, the event log and the frames; what a
// hostile request asks for (another folder, a shot that is not there, a
// frame linked out of the folder, huge ranges, unknown pages) is a 4xx
// naming why, and nothing outside the folders is read.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "store/checked_line.hpp"
#include "telemetry/event_log.hpp"
#include "store/frame_files.hpp"
#include "store/frame_store.hpp"
#include "file_bytes.hpp"
#include "monitor/folder_file.hpp"
#include "monitor/monitor_api.hpp"
#include "monitor/reply_budget.hpp"
#include "render/renderer.hpp"
#include "scratch_dir.hpp"
#include "tiny_frame.hpp"

namespace lc::monitor {
namespace {

namespace fs = std::filesystem;

FrameImage tiny() { return test::tiny_frame(); }

// A folder with three finished frames of "s" (costs 1, 2 and 3
// core-seconds; the last made by ranks 1 and 2, dispatched 2 s before it
// was stored, the others as older journals hold them, without) and a run
// logged as still going with frame 3 in flight.
fs::path render_folder(const test::ScratchDir& scratch) {
  const fs::path dir = scratch / "out";
  {
    farm::FrameStore store(dir, "s");
    const farm::FrameSettings st{4, 2, 1, false, false};
    for (int f = 0; f < 3; ++f)
      store.write_frame(f, tiny(), {}, st, "00000000000000aa", {"00000000000000bb", ""},
                        {.rays = 8, .reused = 0, .core_seconds = 1.0 + f}, Look{},
                        f == 2 ? farm::FrameMakers{{{1, "node-a"}, {2, "node \"b\""}}, 2} : farm::FrameMakers{},
                        f == 2 ? std::optional(std::chrono::steady_clock::now() - std::chrono::seconds(2)) : std::nullopt);
  }
  farm::EventLog log(dir, "s");
  log.run_started({.pid = 9, .host = "n0", .ranks = 1, .threads = 2, .todo = 5, .width = 4, .height = 2});
  for (int f = 0; f < 3; ++f) log.frame_stored(f, 1.0 + f, 8);
  farm::RunProgress p;
  p.frames_stored = 3;
  p.frames_total = 5;
  log.progress(p, {3});
  return dir;
}

bool has(const Reply& r, const std::string& text) { return r.body.find(text) != std::string::npos; }

// The bytes an answer sends: its body, or its part of its file (read
// through the file opened when the answer was made).
std::string sent_bytes(const Reply& r) { return r.file ? r.file->read_at(r.file_offset, r.file_length) : r.body; }

TEST(MonitorApi, StatusCountsTheJournalAndTheRun) {
  test::ScratchDir scratch;
  const MonitorApi api({render_folder(scratch)});
  const Reply folders = api.get("/api/folders", {});
  EXPECT_EQ(folders.status, 200);
  EXPECT_TRUE(has(folders, "\"shots\": [\"s\"]")) << folders.body;
  const Reply s = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
  ASSERT_EQ(s.status, 200) << s.body;
  EXPECT_TRUE(has(s, "\"frames\": {\"done\": 3, \"in_flight\": [3], \"to_do\": 2, \"stale\": 0}")) << s.body;
  EXPECT_TRUE(has(s, "\"state\": \"running\"")) << s.body;
  EXPECT_TRUE(has(s, "\"latest\": [2,1,0]")) << s.body;
  const Reply frames = api.get("/api/frames", {{"folder", "0"}, {"shot", "s"}, {"from", "1"}, {"count", "1"}});
  EXPECT_EQ(frames.body.rfind("{\"total\": 3, \"frames\": [{\"frame\": 1, \"core_seconds\": 2, \"rays\": 8, \"finished\": ", 0), 0u)
      << frames.body;  // one frame: `count` 1 from frame 1
  EXPECT_TRUE(has(frames, "\"next\": 2}")) << frames.body;  // where the rest goes on
  const Reply rest = api.get("/api/frames", {{"folder", "0"}, {"shot", "s"}, {"from", "2"}, {"count", "5"}});
  EXPECT_TRUE(has(rest, "[{\"frame\": 2, ") && has(rest, "\"next\": null}")) << rest.body;
  // Only the frames finished since a time (what the page asks for once it has the rest).
  const std::string later = std::to_string(std::time(nullptr) + 1000);
  const Reply none = api.get("/api/frames", {{"folder", "0"}, {"shot", "s"}, {"since", later}});
  EXPECT_TRUE(has(none, "{\"total\": 3, \"frames\": [], \"next\": null}")) << none.body;
  const Reply events = api.get("/api/events", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(events, "\"event\": \"progress\"")) << events.body;
  // Each frame's ranks and nodes and its wall time, where its line has them.
  const Reply made = api.get("/api/frames", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(made, "\"ranks\": [1,2], \"nodes\": [\"node-a\",\"node \\\"b\\\"\"], \"rank_count\": 2}")) << made.body;
  EXPECT_TRUE(has(made, "\"wall_seconds\": 2.")) << made.body;
  EXPECT_TRUE(has(made, "\"wall_seconds\": null, \"ranks\": [], \"nodes\": [], \"rank_count\": 0}")) << made.body;
  const Reply png = api.get("/api/frame.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "2"}});
  EXPECT_EQ(png.status, 200);
  EXPECT_EQ(png.content_type, "image/png");
  ASSERT_TRUE(png.file) << "a frame is sent from its file, not copied into memory";
  EXPECT_EQ(sent_bytes(png).substr(1, 3), "PNG");
  EXPECT_TRUE(has(api.get("/", {}), "<title>lightcone monitor</title>"));
}

TEST(MonitorApi, HostileRequestsAreRefusedWithFourHundreds) {
  test::ScratchDir scratch;
  const fs::path dir = render_folder(scratch);
  // A frame that links to a file outside the folder.
  std::ofstream(scratch / "secret.png") << "not for the web";
  fs::remove(farm::frame_path(dir, "s", 1, "png"));
  fs::create_symlink(scratch / "secret.png", farm::frame_path(dir, "s", 1, "png"));
  const MonitorApi api({dir}, {}, scratch / "no-chart.js");
  struct Case {
    std::string path;
    Query query;
    int status;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"/api/frame.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "1"}}, 403, "links outside the folder"},
      {"/api/frame.png", {{"folder", "0"}, {"shot", "../s"}, {"frame", "0"}}, 404, "no render of a shot called '../s'"},
      {"/api/frame.png", {{"folder", "0"}, {"shot", "/etc/passwd"}, {"frame", "0"}}, 404, "no render"},
      {"/api/frame.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "-1"}}, 400, "'frame' must be a whole number"},
      {"/api/frame.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "1e9"}}, 400, "'frame'"},
      {"/api/frame.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "7"}}, 404, "frame 7 of 's' has no PNG"},
      {"/api/status", {{"folder", "1"}, {"shot", "s"}}, 400, "'folder' must be a whole number from 0 to 0"},
      {"/api/status", {{"folder", "zero"}, {"shot", "s"}}, 400, "'folder'"},
      {"/api/status", {{"folder", "0"}}, 400, "missing parameter 'shot'"},
      {"/api/frames", {{"folder", "0"}, {"shot", "s"}, {"count", "99999999"}}, 400, "'count' must be a whole number from 1 to 10000"},
      {"/api/frames", {{"folder", "0"}, {"shot", "s"}, {"from", "-5"}}, 400, "'from'"},
      {"/../../etc/passwd", {}, 404, "no such page"},
      {"/etc/passwd", {}, 404, "no such page"},
      {"/chart.js", {}, 404, "install Debian's libjs-chart.js"},
      {"/api/trace", {{"folder", "0"}, {"shot", "s"}, {"frame", "0"}, {"x", "0"}, {"y", "0"}}, 501, "without the pixel inspector"},
  };
  for (const Case& c : cases) {
    const Reply r = api.get(c.path, c.query);
    EXPECT_EQ(r.status, c.status) << c.path << ": " << r.body;
    EXPECT_TRUE(has(r, c.says)) << c.path << ": " << r.body;
    EXPECT_FALSE(has(r, "not for the web")) << c.path;
  }
}

TEST(MonitorApi, ThePixelInspectorRefusesWhatItCannotTrace) {
  test::ScratchDir scratch;
  const MonitorApi api({render_folder(scratch)}, "/bin/false");
  const auto ask = [&](const std::string& frame, const std::string& x, const std::string& y) {
    return api.get("/api/trace", {{"folder", "0"}, {"shot", "s"}, {"frame", frame}, {"x", x}, {"y", y}});
  };
  EXPECT_EQ(ask("5", "0", "0").status, 404);  // not finished
  const Reply outside = ask("0", "4", "0");   // the frames are 4x2
  EXPECT_EQ(outside.status, 400);
  EXPECT_TRUE(has(outside, "'x' must be a whole number from 0 to 3")) << outside.body;
  // The folder's log was written without a script (as by the render of an older lightcone).
  const Reply no_script = ask("0", "1", "1");
  EXPECT_EQ(no_script.status, 409) << no_script.body;
  EXPECT_TRUE(has(no_script, "does not name its shot script")) << no_script.body;
}

TEST(MonitorApi, ADataLayerIsAFalseColourPicture) {
  test::ScratchDir scratch;
  const fs::path dir = render_folder(scratch);
  {
    FrameImage with_layer = tiny();
    with_layer.layers.push_back({"hit.g", {0.5f, 1.0f, 1.5f, 2.0f, 0.f, 1.f, 2.f, std::nanf("")}});
    farm::FrameStore store(dir, "s");
    store.write_frame(3, with_layer, {}, farm::FrameSettings{4, 2, 1, true, false}, "00000000000000aa", {}, {.rays = 8},
                      Look{});
  }
  const MonitorApi api({dir});
  const Reply folders = api.get("/api/folders", {});
  EXPECT_TRUE(has(folders, "\"layers\": [\"hit.kind\", \"hit.r\", \"hit.phi\", \"hit.t\", \"hit.g\", \"hit.order\"]"))
      << folders.body;
  const Reply png = api.get("/api/layer.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "3"}, {"layer", "hit.g"}});
  ASSERT_EQ(png.status, 200) << png.body;
  EXPECT_EQ(png.body.substr(1, 3), "PNG");
  const Reply other = api.get("/api/layer.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "3"}, {"layer", "hit.zz"}});
  EXPECT_EQ(other.status, 404);
  EXPECT_TRUE(has(other, "has no layer 'hit.zz'; it has hit.g")) << other.body;
  const Reply none = api.get("/api/layer.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "0"}, {"layer", "hit.g"}});
  EXPECT_EQ(none.status, 404);
  EXPECT_TRUE(has(none, "render with --layers")) << none.body;
}

TEST(MonitorApi, ARunThatStoppedWithoutAnEndIsSaidToHaveStopped) {
  test::ScratchDir scratch;
  const fs::path dir = scratch / "out";
  fs::create_directories(dir);
  {
    std::ofstream out(farm::events_file(dir, "s"));
    const std::string run = "t=1000.000 event=run pid=1 host=h ranks=1 threads=1 todo=4 done=0 size=4x2";
    out << farm::with_check("lightcone-events 1") << "\n";
    out << farm::with_check(run) << "\n";
  }
  const MonitorApi api({dir});
  const Reply s = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(s, "\"state\": \"stopped\"")) << s.body;
  EXPECT_TRUE(has(s, "\"to_do\": 4")) << s.body;  // left for the same command to resume
}

// The ETA in wall time: the frames left at the rate the run stored its
// latest frames; and the frames left after an interruption.
TEST(MonitorApi, TheEtaIsInWallTimeAndFramesLeftOutliveTheRun) {
  test::ScratchDir scratch;
  const fs::path dir = scratch / "out";
  fs::create_directories(dir);
  const long t0 = static_cast<long>(std::time(nullptr)) - 40;
  {
    std::ofstream out(farm::events_file(dir, "s"));
    out << farm::with_check("lightcone-events 1") << "\n";
    out << farm::with_check(fmt::format("t={} event=run pid=1 host=h ranks=1 threads=8 todo=5 done=0 size=4x2", t0)) << "\n";
    for (int f = 0; f < 3; ++f)  // one every 10 s
      out << farm::with_check(fmt::format("t={} event=frame frame={} core_seconds=80 rays=8", t0 + 10 * (f + 1), f)) << "\n";
    out << farm::with_check(fmt::format("t={} event=progress stored=3 total=5 open=3", t0 + 39)) << "\n";
  }
  const MonitorApi api({dir});
  const Reply running = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(running, "\"state\": \"running\"")) << running.body;
  EXPECT_TRUE(has(running, "\"to_do\": 2")) << running.body;
  // 3 frames in 30 s: 6 a minute, the 2 left in 20 s (not 2 x 80 core-seconds over 8 threads).
  EXPECT_TRUE(has(running, "\"frames_per_minute\": 6, \"eta_seconds\": 20,")) << running.body;
  std::ofstream(farm::events_file(dir, "s"), std::ios::app)
      << farm::with_check(fmt::format("t={} event=end status=interrupted stored=3", t0 + 40)) << "\n";
  const Reply interrupted = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(interrupted, "\"state\": \"interrupted\"")) << interrupted.body;
  EXPECT_TRUE(has(interrupted, "\"to_do\": 2")) << interrupted.body;
  EXPECT_TRUE(has(interrupted, "\"eta_seconds\": null")) << interrupted.body;
}

// An MPI run's workers: each one's state from what the latest progress
// line says it holds, and a lost one (the master gave up on it) as lost.
TEST(MonitorApi, EachWorkerSaysWhatItHoldsOrThatItWasLost) {
  test::ScratchDir scratch;
  const fs::path dir = scratch / "out";
  fs::create_directories(dir);
  farm::EventLog log(dir, "s");
  log.run_started({.pid = 9, .host = "n0", .ranks = 4, .threads = 0, .todo = 5, .width = 4, .height = 2});
  for (int r = 1; r <= 3; ++r) log.rank_joined(r, "n" + std::to_string(r), 2);
  const std::vector<farm::RankHolding> held{{1, 2, {3, 4}}, {2, 0, {}}, {3, 1, {4}}};
  log.progress(farm::RunProgress{}, {3, 4}, &held);
  const MonitorApi api({dir});
  const Reply running = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(running, "{\"rank\": 1, \"host\": \"n1\", \"threads\": 2, \"state\": \"working\", \"sets\": 2, "
                           "\"frames\": [3,4]}")) << running.body;
  EXPECT_TRUE(has(running, "{\"rank\": 2, \"host\": \"n2\", \"threads\": 2, \"state\": \"waiting\", \"sets\": 0, "
                           "\"frames\": []}")) << running.body;
  log.rank_lost(3, "n3");
  log.run_ended("interrupted", 1);
  const Reply ended = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(ended, "\"rank\": 1, \"host\": \"n1\", \"threads\": 2, \"state\": \"interrupted\"")) << ended.body;
  EXPECT_TRUE(has(ended, "\"rank\": 3, \"host\": \"n3\", \"threads\": 2, \"state\": \"lost\"")) << ended.body;
}

// Journals and event logs are read only as regular files inside the
// folder: a link is neither listed as a shot nor followed, and a file that
// is not lightcone's is refused without a word of what it holds.
TEST(MonitorApi, ALinkedOrForeignJournalIsNeverQuoted) {
  test::ScratchDir scratch;
  const fs::path dir = render_folder(scratch);
  std::ofstream(scratch / "passwd") << "root:x:0:0:SECRET-ROOT\ndaemon:x:1:1\nbin:x:2:2\n";
  fs::create_symlink(scratch / "passwd", dir / "leak.journal");
  fs::create_symlink(scratch / "passwd", dir / "count.events");
  fs::copy_file(scratch / "passwd", dir / "foreign.journal");
  const MonitorApi api({dir}, "/bin/false");
  const Reply folders = api.get("/api/folders", {});
  EXPECT_TRUE(has(folders, "\"shots\": [\"foreign\", \"s\"]")) << folders.body;  // no link listed
  for (const std::string shot : {"leak", "count"}) {
    const Reply r = api.get("/api/status", {{"folder", "0"}, {"shot", shot}});
    EXPECT_EQ(r.status, 404) << shot << ": " << r.body;
    EXPECT_FALSE(has(r, "SECRET") || has(r, "bad_event_lines")) << shot << ": " << r.body;
  }
  const Reply foreign = api.get("/api/status", {{"folder", "0"}, {"shot", "foreign"}});
  EXPECT_EQ(foreign.status, 422) << foreign.body;
  EXPECT_TRUE(has(foreign, "foreign.journal is not a lightcone journal")) << foreign.body;
  EXPECT_FALSE(has(foreign, "SECRET")) << foreign.body;
  // A shot the folder holds, whose journal or log is then made a link.
  fs::remove(dir / "s.journal");
  fs::create_symlink(scratch / "passwd", dir / "s.journal");
  for (const std::string page : {"/api/status", "/api/frames", "/api/trace"}) {
    const Reply r = api.get(page, {{"folder", "0"}, {"shot", "s"}, {"frame", "0"}, {"x", "0"}, {"y", "0"}});
    EXPECT_EQ(r.status, 403) << page << ": " << r.body;
    EXPECT_TRUE(has(r, "s.journal is a link")) << page << ": " << r.body;
    EXPECT_FALSE(has(r, "SECRET")) << page << ": " << r.body;
  }
  // A shot whose journal is its own and whose log links out.
  fs::copy_file(scratch / "passwd", scratch / "e.events");
  fs::create_symlink(scratch / "e.events", farm::events_file(dir, "e"));
  farm::FrameStore(dir, "e").write_frame(0, tiny(), {}, farm::FrameSettings{4, 2, 1, false, false}, "00000000000000aa", {},
                                          {.rays = 8}, Look{});
  for (const std::string page : {"/api/status", "/api/events"}) {
    const Reply r = api.get(page, {{"folder", "0"}, {"shot", "e"}});
    EXPECT_EQ(r.status, 403) << page << ": " << r.body;
    EXPECT_TRUE(has(r, "e.events is a link")) << page << ": " << r.body;
  }
}

// A journal that is a FIFO or a link to a device that never ends is
// refused at once: it must not hold a request (and the server's threads)
// for ever.
TEST(MonitorApi, AJournalThatNeverEndsIsRefusedAtOnce) {
  test::ScratchDir scratch;
  const fs::path dir = render_folder(scratch);
  const MonitorApi api({dir});
  const auto status_within = [&](std::chrono::seconds limit) {
    // Run where a regression may hang for good: the thread is then left
    // behind (reading /dev/zero) and the test fails.
    auto reply = std::make_shared<std::promise<Reply>>();
    auto answer = reply->get_future();
    std::thread([&api, reply] { reply->set_value(api.get("/api/status", {{"folder", "0"}, {"shot", "s"}})); }).detach();
    if (answer.wait_for(limit) != std::future_status::ready) return Reply{0, "", "no answer"};
    return answer.get();
  };
  fs::remove(dir / "s.journal");
  {
    const test::UnblockedFifo fifo(dir / "s.journal");
    const auto start = std::chrono::steady_clock::now();
    const Reply r = status_within(std::chrono::seconds(10));
    EXPECT_EQ(r.status, 403) << r.body;
    EXPECT_TRUE(has(r, "s.journal is not a regular file")) << r.body;
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  }
  fs::remove(dir / "s.journal");
  fs::create_symlink("/dev/zero", dir / "s.journal");
  const Reply r = status_within(std::chrono::seconds(5));
  EXPECT_EQ(r.status, 403) << r.body;
  EXPECT_TRUE(has(r, "s.journal is a link")) << r.body;
}

// The pixel inspector runs one trace at a time (429 to the others while
// it runs), answers a pixel traced before from its cache, and runs the
// trace niced.  The tracer here stands in for the lightcone binary
// (tests/e2e/monitor.sh runs the real one): it counts its runs, takes a
// second and reports its niceness.
TEST(MonitorApi, ThePixelInspectorTracesOnePixelAtATime) {
  test::ScratchDir scratch;
  const fs::path dir = render_folder(scratch);
  std::ofstream(scratch / "shot.lua") << "-- the shot\n";
  {
    farm::EventLog log(dir, "s");
    log.run_started({.pid = 9, .host = "n0", .ranks = 1, .threads = 2, .todo = 5, .done_before = 0, .width = 4,
                     .height = 2, .script = (scratch / "shot.lua").string()});
  }
  const fs::path tracer = scratch / "tracer.sh";
  std::ofstream(tracer) << "#!/bin/sh\necho run >>'" << (scratch / "runs").string()
                        << "'\nsleep 1\necho \"{\\\"nice\\\": $(nice)}\"\n";
  fs::permissions(tracer, fs::perms::owner_all);
  const MonitorApi api({dir}, tracer);
  const auto ask = [&](const std::string& x) {
    return api.get("/api/trace", {{"folder", "0"}, {"shot", "s"}, {"frame", "1"}, {"x", x}, {"y", "1"}});
  };
  Reply first;
  std::thread tracing([&] { first = ask("1"); });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const Reply busy = ask("2");
  tracing.join();
  ASSERT_EQ(first.status, 200) << first.body;
  EXPECT_TRUE(has(first, "\"report\": {\"nice\": 10}")) << first.body;
  EXPECT_EQ(busy.status, 429) << busy.body;
  EXPECT_TRUE(has(busy, "tracing another pixel")) << busy.body;
  const auto start = std::chrono::steady_clock::now();
  const Reply again = ask("1");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(500));
  EXPECT_EQ(again.body, first.body);
  std::ifstream runs(scratch / "runs");
  int count = 0;
  for (std::string line; std::getline(runs, line);) ++count;
  EXPECT_EQ(count, 1);
}

TEST(MonitorApi, OnlyDirectoriesAreServed) {
  test::ScratchDir scratch;
  std::ofstream(scratch / "file") << "x";
  EXPECT_THROW(MonitorApi({scratch / "file"}), std::invalid_argument);
  EXPECT_THROW(MonitorApi({scratch / "missing"}), std::invalid_argument);
  EXPECT_THROW(MonitorApi(std::vector<fs::path>{}), std::invalid_argument);
}

}  // namespace
}  // namespace lc::monitor

namespace lc::monitor {
namespace {

// One byte range is served 206 with its Content-Range; several, or one
// past the end, 416 with the size; a range that does not parse, or of
// another unit, is ignored (200, the whole answer); only a 200 is cut.
TEST(MonitorApi, OneRangeIsAnsweredWithItsPart) {
  const Reply whole{200, "text/plain", "0123456789"};
  const auto part = [&](const std::string& range) { return with_range(whole, range); };
  EXPECT_EQ(part("bytes=2-4").reply.status, 206);
  EXPECT_EQ(part("bytes=2-4").reply.body, "234");
  EXPECT_EQ(part("bytes=2-4").content_range, "bytes 2-4/10");
  EXPECT_EQ(part("bytes=7-").reply.body, "789");
  EXPECT_EQ(part(" bytes=8-99999999999999999999999").content_range, "bytes 8-9/10");
  EXPECT_EQ(part("bytes=-3").reply.body, "789");
  EXPECT_EQ(part("bytes=-30").content_range, "bytes 0-9/10");
  EXPECT_EQ(part("bytes=10-").reply.status, 416);
  EXPECT_EQ(part("bytes=10-").content_range, "bytes */10");
  EXPECT_EQ(part("bytes=99999999999999999999999-").reply.status, 416);
  EXPECT_EQ(part("bytes=-0").reply.status, 416);
  EXPECT_EQ(part("bytes=0-1,3-4").reply.status, 416);
  for (const std::string ignored : {"", "items=0-1", "bytes=4-2", "bytes=x-2", "bytes=1", "bytes=--1"}) {
    EXPECT_EQ(part(ignored).reply.status, 200) << ignored;
    EXPECT_EQ(part(ignored).reply.body, "0123456789") << ignored;
    EXPECT_EQ(part(ignored).content_range, "") << ignored;
  }
  const RangedReply missing = with_range(error_reply(404, "no such page"), "bytes=0-1");
  EXPECT_EQ(missing.reply.status, 404);
  EXPECT_EQ(missing.content_range, "");
}

// A frame is sent from the file opened for it, at the size it had then
// (the file grows after: the answer does not), and a range of it is only
// an offset and a length in that file.
TEST(MonitorApi, AFrameIsSentFromItsFileAtItsSizeWhenOpened) {
  test::ScratchDir scratch;
  const fs::path dir = render_folder(scratch);
  const fs::path png = farm::frame_path(dir, "s", 2, "png");
  const MonitorApi api({dir});
  const Reply whole = api.get("/api/frame.png", {{"folder", "0"}, {"shot", "s"}, {"frame", "2"}});
  ASSERT_EQ(whole.status, 200) << whole.body;
  ASSERT_TRUE(whole.file);
  EXPECT_TRUE(whole.body.empty());
  const std::uint64_t size = fs::file_size(png);
  EXPECT_EQ(whole.size(), size);
  std::ofstream(png, std::ios::app) << "appended after the answer was made";
  const std::string on_disk = test::bytes_of(png);
  EXPECT_EQ(sent_bytes(whole), on_disk.substr(0, size));
  const RangedReply part = with_range(whole, "bytes=3-9");
  EXPECT_EQ(part.reply.status, 206);
  EXPECT_EQ(part.content_range, fmt::format("bytes 3-9/{}", size));
  EXPECT_EQ(sent_bytes(part.reply), on_disk.substr(3, 7));
  const RangedReply tail = with_range(whole, "bytes=-4");
  EXPECT_EQ(sent_bytes(tail.reply), on_disk.substr(size - 4, 4));
  EXPECT_EQ(with_range(whole, fmt::format("bytes={}-", size)).reply.status, 416);
}

// The server's budget for bodies built in memory: what would go past it is
// refused and takes nothing; what is given back can be taken again; many
// threads taking and giving at once never hold more than it.
TEST(ReplyBudget, RefusesWhatWouldGoPastItAndTakesBackWhatIsFreed) {
  ReplyBudget budget(100);
  EXPECT_TRUE(budget.take(60));
  EXPECT_FALSE(budget.take(41));
  EXPECT_EQ(budget.held(), 60u);
  EXPECT_TRUE(budget.take(40));
  EXPECT_FALSE(budget.take(1));
  EXPECT_FALSE(budget.take(SIZE_MAX));  // no wrap past the capacity
  budget.give(60);
  EXPECT_TRUE(budget.take(60));
  budget.give(100);
  EXPECT_EQ(budget.held(), 0u);
  EXPECT_FALSE(budget.take(101));

  ReplyBudget shared(1000);
  std::atomic<std::size_t> most{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&] {
      for (int k = 0; k < 20000; ++k)
        if (shared.take(300)) {
          std::size_t seen = shared.held(), was = most.load();
          while (seen > was && !most.compare_exchange_weak(was, seen)) {
          }
          shared.give(300);
        }
    });
  for (auto& t : threads) t.join();
  EXPECT_EQ(shared.held(), 0u);
  EXPECT_LE(most.load(), 900u);  // three bodies of 300 at most, never a fourth
}

}  // namespace
}  // namespace lc::monitor

namespace lc::monitor {
namespace {

// The run's command line and folder, as its log records them, come back as
// one shell line that resumes it: words the shell would read otherwise
// quoted; an MPI run's launcher put first; none from an older log.
TEST(MonitorApi, TheStatusGivesTheCommandThatResumesTheRun) {
  test::ScratchDir scratch;
  const fs::path dir = scratch / "out";
  fs::create_directories(dir);
  {
    farm::EventLog log(dir, "s");
    log.run_started({.pid = 9, .host = "n0", .todo = 5, .width = 4, .height = 2, .script = "/shots/s.lua",
                     .command = {"lightcone", "render", "my shot's.lua", "--out", "o", "--frames", "0:9"},
                     .cwd = "/home/me/films"});
    log.frame_stored(0, 1.0, 8);
  }
  const MonitorApi api({dir});
  const Reply status = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(status, R"("resume": "cd /home/me/films && lightcone render 'my shot'\\''s.lua' --out o --frames 0:9")"))
      << status.body;
  // The event log's run line shows the same words, without the NULs that
  // separate them in the log.
  const Reply events = api.get("/api/events", {{"folder", "0"}, {"shot", "s"}});
  EXPECT_TRUE(has(events, R"("command": "lightcone render 'my shot'\\''s.lua' --out o --frames 0:9")")) << events.body;
  EXPECT_FALSE(has(events, "\\u0000"));
  {
    farm::EventLog log(dir, "s");
    log.run_started({.pid = 10, .host = "n0", .ranks = 3, .todo = 5, .command = {"lightcone", "render", "s.lua"}, .cwd = "/w"});
  }
  EXPECT_TRUE(has(api.get("/api/status", {{"folder", "0"}, {"shot", "s"}}), R"("resume": "cd /w && mpirun -n 3 lightcone render s.lua")"));
  {
    farm::EventLog log(dir, "s");
    log.run_started({.pid = 11, .host = "n0", .todo = 5});
  }
  EXPECT_TRUE(has(api.get("/api/status", {{"folder", "0"}, {"shot", "s"}}), R"("resume": null)"));
}

}  // namespace
}  // namespace lc::monitor

namespace lc::monitor {
namespace {

// A parent folder's render folders are listed as they appear: down to
// max_folder_depth, not through links, not in hidden folders, not inside a
// render folder; each keeps its number.
TEST(MonitorApi, RenderFoldersUnderAParentAreFoundAsTheyAppear) {
  test::ScratchDir scratch;
  const fs::path parent = scratch / "films";
  const auto render = [](const fs::path& dir) {
    fs::create_directories(dir);
    farm::EventLog log(dir, "s");
    log.run_started({.pid = 9, .host = "n0", .todo = 5});
    log.frame_stored(0, 1.0, 8);
  };
  render(parent / "a");
  render(parent / "b" / "take1");
  render(parent / "a" / "inner");                    // inside a render folder: its own
  render(parent / ".trash" / "old");                 // hidden
  render(parent / "d1" / "d2" / "d3" / "d4");        // too deep
  render(scratch / "elsewhere");
  fs::create_directory_symlink(scratch / "elsewhere", parent / "link");  // a link: not followed
  fs::create_directories(parent / "empty");
  const MonitorApi api({parent});
  const std::string root = fs::canonical(parent).string();
  const Reply first = api.get("/api/folders", {});
  EXPECT_TRUE(has(first, fmt::format(R"({{"id": 0, "path": "{}", "shots": []}})", root))) << first.body;
  EXPECT_TRUE(has(first, fmt::format(R"("path": "{}/a", "shots": ["s"])", root))) << first.body;
  EXPECT_TRUE(has(first, fmt::format(R"("path": "{}/b/take1", "shots": ["s"])", root))) << first.body;
  for (const char* never : {"inner", "trash", "d4", "elsewhere", "link", "empty"}) EXPECT_FALSE(has(first, never)) << never;
  EXPECT_EQ(api.folders().size(), 3u);
  const std::size_t a = api.folders()[1] == fs::canonical(parent / "a") ? 1 : 2;

  // A render that starts later is listed at the next poll, after the others.
  render(parent / "empty" / "late");
  const Reply second = api.get("/api/folders", {});
  EXPECT_TRUE(has(second, fmt::format(R"({{"id": 3, "path": "{}/empty/late", "shots": ["s"]}})", root))) << second.body;
  EXPECT_EQ(api.folders()[a], fs::canonical(parent / "a"));
  EXPECT_EQ(api.get("/api/status", {{"folder", "3"}, {"shot", "s"}}).status, 200);
  EXPECT_EQ(api.get("/api/status", {{"folder", "4"}, {"shot", "s"}}).status, 400);
}

}  // namespace
}  // namespace lc::monitor

namespace lc::monitor {
namespace {

// What ended a run is named: the rank lost (with its node), else the
// error, else a signal; nothing for a run that finished.
TEST(MonitorApi, TheStatusNamesWhatEndedTheRun) {
  test::ScratchDir scratch;
  const fs::path dir = scratch / "out";
  fs::create_directories(dir);
  const MonitorApi api({dir});
  const auto ended = [&](auto&& log_run) {
    {
      farm::EventLog log(dir, "s");
      log.run_started({.pid = 9, .host = "n0", .ranks = 3, .todo = 5});
      log.frame_stored(0, 1.0, 8);
      log_run(log);
    }
    const Reply r = api.get("/api/status", {{"folder", "0"}, {"shot", "s"}});
    const auto at = r.body.find("\"ended_by\": ");
    return at == std::string::npos ? r.body : r.body.substr(at + 12, r.body.find('}', at) - at - 12);
  };
  EXPECT_EQ(ended([](farm::EventLog& log) {
              log.rank_joined(1, "n1", 2);
              log.rank_joined(2, "n2", 2);
              log.rank_lost(2, "n2");
              log.run_ended("interrupted", 1);
            }),
            "\"rank 2 on n2 stopped answering (lost)\"");
  EXPECT_EQ(ended([](farm::EventLog& log) {
              log.error("s.lua:3: attempt to call a nil value");
              log.run_ended("error", 1);
            }),
            "\"s.lua:3: attempt to call a nil value\"");
  EXPECT_EQ(ended([](farm::EventLog& log) { log.run_ended("interrupted", 1); }),
            "\"a signal: Ctrl-C, a kill, or the launcher ending the job\"");
  EXPECT_EQ(ended([](farm::EventLog& log) { log.run_ended("done", 1); }), "null");
}

}  // namespace
}  // namespace lc::monitor
