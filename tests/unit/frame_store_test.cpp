// The frame store: one render per directory (the lock names its holder),
// what resume trusts (journal line + files of the recorded sizes), and the
// cleanup of temporaries a killed render left behind, and a preview's
// missing rows filled from the nearest rendered one.

#include <chrono>
#include <csignal>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include "store/checked_line.hpp"
#include "store/frame_files.hpp"
#include "store/frame_store.hpp"
#include "job/resume_plan.hpp"
#include "image/image_io.hpp"
#include "render/renderer.hpp"
#include "scratch_dir.hpp"
#include "test_errors.hpp"
#include "tiny_frame.hpp"

namespace lc::farm {
namespace {

FrameImage tiny() { return test::tiny_frame(); }

TEST(FrameStore, SecondStoreOnTheDirectoryIsRefusedNamingThePid) {
  test::ScratchDir dir;
  FrameStore first(dir / "out", "s");
  try {
    FrameStore second(dir / "out", "s");
    FAIL() << "second store took the lock";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("another lightcone render is writing there"), std::string::npos) << msg;
    EXPECT_NE(msg.find("pid " + std::to_string(::getpid())), std::string::npos) << msg;
  }
}

TEST(FrameStore, LockIsReleasedAndRemoved) {
  test::ScratchDir dir;
  { FrameStore first(dir / "out", "s"); }
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / DirLock::file_name));
  EXPECT_NO_THROW(FrameStore again(dir / "out", "s"));
}

// Runs `f` with files limited to `bytes` (ulimit -f): a write past it fails
// with EFBIG, as one onto a full disk fails, without root or a small disk.
template <class F>
void with_file_limit(rlim_t bytes, F&& f) {
  rlimit old{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // the error, not the signal that kills
  rlimit lim = old;
  lim.rlim_cur = bytes;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &lim), 0);
  f();
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
}

TEST(FrameStore, ALockFileItMadeAndCouldNotUseIsRemovedOneThatWasThereIsLeft) {
  // A full disk left an empty lightcone.lock behind (issue 43).
  test::ScratchDir dir;
  std::filesystem::create_directories(dir / "out");
  const auto lock = dir / "out" / DirLock::file_name;
  with_file_limit(0, [&] {
    const std::string message = test::error_of([&] { FrameStore store(dir / "out", "s"); });
    EXPECT_NE(message.find("cannot write to the output directory (" + lock.string() + ": File too large)"),
              std::string::npos)
        << message;
  });
  EXPECT_FALSE(std::filesystem::exists(lock));
  // One a killed render left stays (nobody's lock, but not this run's to remove).
  std::ofstream(lock) << "pid 1 on elsewhere\n";
  with_file_limit(4, [&] { EXPECT_THROW(FrameStore store(dir / "out", "s"), std::runtime_error); });
  EXPECT_TRUE(std::filesystem::exists(lock));
}

TEST(FrameStore, ItsOwnFilesAreNeverLinksOrFifos) {
  // A link under the lock's or the journal's name was written through; a
  // FIFO under the journal's name hung the render that held the lock.
  test::ScratchDir dir;
  std::ofstream(dir / "outside.txt") << "not lightcone's";
  std::filesystem::create_directories(dir / "a");
  std::filesystem::create_symlink(dir / "outside.txt", dir / "a" / DirLock::file_name);
  std::string message = test::error_of([&] { FrameStore store(dir / "a", "s"); });
  EXPECT_NE(message.find((dir / "a" / DirLock::file_name).string() + ": it is a symbolic link"), std::string::npos)
      << message;
  std::filesystem::create_directories(dir / "b");
  const test::UnblockedFifo fifo(dir / "b" / "s.journal");
  const auto start = std::chrono::steady_clock::now();
  message = test::error_of([&] { FrameStore store(dir / "b", "s"); });
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(3));
  EXPECT_NE(message.find(fifo.path().string() + ": it is a FIFO"), std::string::npos) << message;
  EXPECT_FALSE(std::filesystem::exists(dir / "b" / DirLock::file_name));  // the lock went with the refusal
  std::ifstream in(dir / "outside.txt");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "not lightcone's");
}

TEST(FrameStore, ResumeTrustsJournalAndFileSizes) {
  test::ScratchDir dir;
  const FrameSettings st{4, 2, 1, false};
  {
    FrameStore store(dir.path(), "s");
    store.write_frame(0, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8}, Look{});
    store.write_frame(1, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8}, Look{});
    store.write_frame(2, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8}, Look{});
  }
  // A frame file without a journal line, and a damaged frame.
  write_exr(frame_path(dir.path(), "s", 3, "exr"), tiny());
  write_png(frame_path(dir.path(), "s", 3, "png"), tiny());
  std::filesystem::resize_file(frame_path(dir.path(), "s", 1, "exr"), 10);
  std::filesystem::remove(frame_path(dir.path(), "s", 2, "png"));
  FrameStore store(dir.path(), "s");
  EXPECT_EQ(store.state(0, st, "00000000000000aa"), FrameState::done);
  EXPECT_EQ(store.state(1, st, "00000000000000aa"), FrameState::damaged);
  EXPECT_EQ(store.state(2, st, "00000000000000aa"), FrameState::damaged);
  EXPECT_EQ(store.state(3, st, "00000000000000aa"), FrameState::todo);
  EXPECT_EQ(store.state(0, st, "00000000000000bb"), FrameState::stale);
  EXPECT_EQ(store.state(0, {8, 4, 1, false}, "00000000000000aa"), FrameState::stale);
}

// A stored frame's line records who rendered it and the wall time from
// its dispatch until its files were stored; a journal an earlier lightcone
// wrote (lines without them) still resumes: its frames are done.
TEST(FrameStore, AFrameRecordsWhoMadeItAndAnOlderJournalStillResumes) {
  test::ScratchDir dir;
  const FrameSettings st{4, 2, 1, false};
  const auto dispatched = std::chrono::steady_clock::now() - std::chrono::milliseconds(1500);
  {
    FrameStore store(dir.path(), "s");
    store.write_frame(0, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8, .reused = 0, .core_seconds = 0.5}, Look{},
                      {{{1, "node-a"}, {2, "node-b"}}, 2}, dispatched);
    store.write_frame(1, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8}, Look{});
  }
  const JournalContents j = read_journal(dir / "s.journal");
  EXPECT_EQ(j.frames.at(0).makers, (FrameMakers{{{1, "node-a"}, {2, "node-b"}}, 2}));
  EXPECT_GE(j.frames.at(0).cost.wall_seconds, 1.5);
  EXPECT_LT(j.frames.at(0).cost.wall_seconds, 60.0);
  EXPECT_EQ(j.frames.at(1).cost.wall_seconds, -1.0);  // no dispatch known: none recorded
  EXPECT_TRUE(j.frames.at(1).makers.ranks.empty());

  // The same folder's journal as an earlier lightcone wrote it: its lines
  // without the new fields (written out literally), then resumed.
  const auto exr = std::filesystem::file_size(frame_path(dir.path(), "s", 0, "exr"));
  const auto png = std::filesystem::file_size(frame_path(dir.path(), "s", 0, "png"));
  {
    std::ofstream old(dir / "s.journal", std::ios::binary | std::ios::trunc);
    old << journal_header_line() << "\n"
        << with_check(fmt::format("frame=0 size=4x2 supersample=1 layers=0 sampling=full inputs=00000000000000aa "
                                  "exr={} png={} rays=8 reused=0 core_seconds=0.500 star_seconds=0.000 finished=1764000000",
                                  exr, png))
        << "\n";
  }
  FrameStore store(dir.path(), "s");
  EXPECT_EQ(store.journal().bad_lines, 0);
  EXPECT_EQ(store.state(0, st, "00000000000000aa"), FrameState::done);
  EXPECT_EQ(store.state(1, st, "00000000000000aa"), FrameState::todo);
  // Appending to it keeps the older line as it was.
  store.write_frame(1, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8}, Look{}, {{{0, "here"}}, 1},
                    std::chrono::steady_clock::now());
  const JournalContents resumed = read_journal(dir / "s.journal");
  EXPECT_EQ(resumed.frames.size(), 2u);
  EXPECT_TRUE(resumed.frames.at(0).makers.ranks.empty());
  EXPECT_EQ(resumed.frames.at(1).makers, (FrameMakers{{{0, "here"}}, 1}));
  EXPECT_GE(resumed.frames.at(1).cost.wall_seconds, 0.0);
}

TEST(FrameStore, RefusalNamesTheChangedInputAndForceRendersOnlyThose) {
  test::ScratchDir dir;
  const FrameSettings st{4, 2, 1, false};
  {
    FrameStore store(dir.path(), "s");
    store.note_inputs({{"/x/shot.lua", "00000000000000aa"}});
    store.write_frame(0, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8}, Look{});
    store.write_frame(1, tiny(), {}, st, "00000000000000cc", {}, {.rays = 8}, Look{});
  }
  FrameStore store(dir.path(), "s");
  ShotSurvey survey;
  survey.files["/x/shot.lua"] = "00000000000000bb";
  survey.frames[0].inputs = "00000000000000bb";
  survey.frames[1].inputs = "00000000000000cc";
  survey.frames[2].inputs = "00000000000000bb";
  try {
    plan_resume(store, survey, st, {0, 1, 2}, false, "s");
    FAIL() << "changed inputs accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("other versions of: /x/shot.lua"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
  const ResumePlan plan = plan_resume(store, survey, st, {0, 1, 2}, true, "s");
  EXPECT_EQ(plan.todo, (std::vector<int>{0, 2}));
  EXPECT_EQ(plan.stale, (std::vector<int>{0}));
  EXPECT_EQ(plan.done, (std::vector<int>{1}));
}

// A file the journal never recorded (a catalogue now at another path) is
// named, not "other inputs" (issue 43).
TEST(FrameStore, RefusalNamesAFileTheFramesDidNotRead) {
  test::ScratchDir dir;
  const FrameSettings st{4, 2, 1, false};
  {
    FrameStore store(dir.path(), "s");
    store.note_inputs({{"/x/shot.lua", "00000000000000aa"}, {"/x/stars.dat", "00000000000000dd"}});
    store.write_frame(0, tiny(), {}, st, "00000000000000aa", {}, {.rays = 8}, Look{});
  }
  FrameStore store(dir.path(), "s");
  ShotSurvey survey;
  survey.files["/x/shot.lua"] = "00000000000000aa";
  survey.files["/y/other.dat"] = "00000000000000ee";
  survey.frames[0].inputs = "00000000000000bb";
  const std::string e = test::error_of([&] { plan_resume(store, survey, st, {0}, false, "s"); });
  EXPECT_NE(e.find("frame 0 was rendered from other files than this render reads: /y/other.dat was not among them"),
            std::string::npos)
      << e;
}

TEST(FrameStore, TemporariesOfAKilledRenderAreRemoved) {
  test::ScratchDir dir;
  std::ofstream(dir / "s.0003.exr.tmp-12345") << "half";
  std::ofstream(dir / "other.0003.exr.tmp-12345") << "not ours";
  std::ofstream(dir / "s.notes.txt") << "not a temporary";
  FrameStore store(dir.path(), "s");
  EXPECT_FALSE(std::filesystem::exists(dir / "s.0003.exr.tmp-12345"));
  EXPECT_TRUE(std::filesystem::exists(dir / "other.0003.exr.tmp-12345"));
  EXPECT_TRUE(std::filesystem::exists(dir / "s.notes.txt"));
}

TEST(FrameStore, MissingRowsComeFromTheNearestRenderedRow) {
  FrameImage img;
  img.width = 1;
  img.height = 9;
  img.rgb.assign(27, 0.0f);
  img.alpha.assign(9, 1.0f);
  for (int j : {0, 4, 8}) img.rgb[3 * j] = img.alpha[j] = static_cast<float>(j) / 8;
  fill_missing_rows(img, {0, 4, 8});
  std::vector<float> r;
  for (int j = 0; j < 9; ++j) r.push_back(img.rgb[3 * j] * 8);
  EXPECT_EQ(r, (std::vector<float>{0, 0, 0, 4, 4, 4, 4, 8, 8}));  // ties go to the row above
  for (int j = 0; j < 9; ++j) EXPECT_EQ(img.alpha[j], img.rgb[3 * j]);  // alpha comes from the same row
  FrameImage one = img;
  one.alpha.clear();
  one.rgb.assign(27, 0.0f);
  one.rgb[3 * 5] = 5;
  fill_missing_rows(one, {5});
  for (int j = 0; j < 9; ++j) EXPECT_EQ(one.rgb[3 * j], 5.0f);
}

}  // namespace
}  // namespace lc::farm
