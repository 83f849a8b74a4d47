// The monitor's cache of parsed files (monitor/parsed_cache.hpp): a journal
// or event log read again after lines were appended parses only the
// appended tail, and gives exactly what a full parse of the file gives,
// torn lines, bad lines, a new run and rewrites included.

#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "store/checked_line.hpp"
#include "telemetry/event_log.hpp"
#include "store/journal.hpp"
#include "monitor/folder_file.hpp"
#include "monitor/parsed_cache.hpp"
#include "scratch_dir.hpp"

namespace lc::monitor {
namespace {

namespace fs = std::filesystem;

std::string frame_line(int frame, double seconds) {
  farm::JournalFrame f;
  f.frame = frame;
  f.settings = {4, 2, 1, false, false};
  f.inputs = "00000000000000aa";
  f.parts = {"00000000000000bb", ""};
  f.png_bytes = 100 + frame;
  f.cost = {.rays = 8, .reused = 0, .core_seconds = seconds, .finished = 1000 + frame};
  return farm::journal_frame_line(f) + "\n";
}

void append(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::app | std::ios::binary) << text;
}

// Everything a reader of the contents sees, as one string to compare.
std::string summary(const farm::JournalContents& j) {
  std::string out = fmt::format("last={} bad={} torn={} valid={} inputs={}\n", j.last_frame, j.bad_lines, j.torn_tail,
                                j.valid_bytes, j.inputs.size());
  for (const auto& [path, hash] : j.inputs) out += path + "=" + hash + "\n";
  for (const auto& [f, jf] : j.frames)
    out += fmt::format("{} {} {} {}\n", f, jf.png_bytes, jf.cost.core_seconds, jf.cost.finished);
  return out;
}

// The cache's answer for `p` and the bytes it parsed for it.
std::string cached(JournalCache& cache, const fs::path& p, std::uintmax_t& parsed) {
  const FolderFile file(p);
  const std::string out = summary(*cache.read(file, p.string()));
  parsed = cache.last_parsed_bytes();
  return out;
}

TEST(JournalCache, AnAppendedTailGivesWhatAFullParseGives) {
  test::ScratchDir scratch;
  const fs::path p = scratch / "s.journal";
  std::string text = farm::journal_header_line() + "\n" + farm::journal_input_line("00000000000000cc", "/sky.exr") + "\n";
  for (int f = 0; f < 50; ++f) text += frame_line(f, 1.0);
  append(p, text);
  const std::string torn = frame_line(50, 2.0);
  append(p, torn.substr(0, 40));  // a line being written as the monitor reads
  JournalCache cache;
  std::uintmax_t parsed = 0;
  EXPECT_EQ(cached(cache, p, parsed), summary(farm::read_journal(p)));
  EXPECT_EQ(parsed, text.size());

  // The torn line finished, a frame redone, a bad line, an input line, and
  // another torn line: only the tail is parsed, and it comes out the same.
  const std::string tail = torn.substr(40) + frame_line(3, 5.0) + "frame=7 junk #0000000000000000\n" +
                           farm::journal_input_line("00000000000000dd", "/sky.exr") + "\n" + frame_line(51, 3.0) +
                           "frame=52 size=";
  append(p, tail);
  EXPECT_EQ(cached(cache, p, parsed), summary(farm::read_journal(p)));
  EXPECT_EQ(parsed, 40 + tail.size() - std::string("frame=52 size=").size());  // from the torn line on
  EXPECT_NE(summary(farm::read_journal(p)).find("3 103 5 1003"), std::string::npos);

  // Unchanged: nothing parsed.
  EXPECT_EQ(cached(cache, p, parsed), summary(farm::read_journal(p)));
  EXPECT_EQ(parsed, 0u);

  // The writer cuts the torn line off and appends: still only the tail.
  fs::resize_file(p, fs::file_size(p) - std::string("frame=52 size=").size());
  append(p, frame_line(52, 4.0));
  EXPECT_EQ(cached(cache, p, parsed), summary(farm::read_journal(p)));
  EXPECT_EQ(parsed, frame_line(52, 4.0).size());
}

TEST(JournalCache, AJournalRewrittenOrReplacedIsParsedWhole) {
  test::ScratchDir scratch;
  const fs::path p = scratch / "s.journal";
  std::string text = farm::journal_header_line() + "\n";
  for (int f = 0; f < 20; ++f) text += frame_line(f, 1.0);
  append(p, text);
  JournalCache cache;
  std::uintmax_t parsed = 0;
  cached(cache, p, parsed);

  // Rewritten in place, longer: the bytes before where the parse stopped
  // changed, so the whole file is parsed again.
  std::string other = farm::journal_header_line() + "\n";
  for (int f = 0; f < 25; ++f) other += frame_line(f, 9.0);
  std::ofstream(p, std::ios::binary | std::ios::in | std::ios::out) << other;
  EXPECT_EQ(cached(cache, p, parsed), summary(farm::read_journal(p)));
  EXPECT_EQ(parsed, other.size());

  // Shorter (another journal moved in its place): parsed whole.
  const fs::path q = scratch / "t.journal";
  append(q, farm::journal_header_line() + "\n" + frame_line(7, 2.0));
  fs::rename(q, p);
  EXPECT_EQ(cached(cache, p, parsed), summary(farm::read_journal(p)));
  EXPECT_EQ(parsed, fs::file_size(p));
}

// An event log's summary, as one string to compare.
std::string summary(const farm::EventSummary& s) {
  std::string out = fmt::format("run={} ranks={} lost={} progress={} end={} errors={} stored={} bad={}\n",
                                s.run ? s.run->pid : -1, s.ranks.size(), s.lost.size(),
                                s.progress ? s.progress->fields.at("stored") : "-",
                                s.end ? s.end->fields.at("status") : "-", s.errors.size(), s.frames_stored, s.bad_lines);
  for (const farm::Event& e : s.recent) out += fmt::format("{} {} {}\n", e.time, e.kind, e.fields.size());
  return out;
}

std::string cached_events(EventCache& cache, const fs::path& p, std::uintmax_t& parsed) {
  const FolderFile file(p);
  const std::string out = summary(*cache.read(file, p.string()));
  parsed = cache.last_parsed_bytes();
  return out;
}

TEST(EventCache, AnAppendedTailGivesWhatAFullParseGives) {
  test::ScratchDir scratch;
  const fs::path p = scratch / "s.events";
  const auto line = [](const std::string& content) { return farm::with_check(content) + "\n"; };
  std::string text = line("lightcone-events 1") + line("t=1 event=run pid=7 host=a ranks=1 threads=2 todo=300 done=0");
  for (int f = 0; f < 150; ++f) text += line(fmt::format("t={} event=frame frame={} core_seconds=1 rays=8", 2 + f, f));
  text += line("t=200 event=error message=disk%20full") + "t=201 event=junk #0000000000000000\n";
  append(p, text);
  EventCache cache;
  std::uintmax_t parsed = 0;
  EXPECT_EQ(cached_events(cache, p, parsed), summary(farm::read_events(p)));

  // More frames (the last 200 events now span both parses), a progress
  // line, a torn line: only the tail is read.
  std::string more;
  for (int f = 150; f < 260; ++f) more += line(fmt::format("t={} event=frame frame={} core_seconds=1 rays=8", 300 + f, f));
  more += line("t=600 event=progress stored=260 total=300 rows=1/2 rays=9 core_seconds=3 open=260") + "t=601 event=fr";
  append(p, more);
  EXPECT_EQ(cached_events(cache, p, parsed), summary(farm::read_events(p)));
  EXPECT_EQ(parsed, more.size() - std::string("t=601 event=fr").size());

  // The torn line finished, the run ended, and a new run began.
  const std::string next = std::string("ame frame=260 core_seconds=1 rays=8 #0000000000000000\n") +
                           line("t=602 event=end status=interrupted stored=260") +
                           line("t=700 event=run pid=8 host=b ranks=2 threads=4 todo=40 done=260") +
                           line("t=701 event=rank rank=1 host=c threads=2") + line("t=702 event=lost rank=1 host=c");
  append(p, next);
  EXPECT_EQ(cached_events(cache, p, parsed), summary(farm::read_events(p)));
  EXPECT_NE(summary(farm::read_events(p)).find("run=8 ranks=1 lost=1"), std::string::npos);
}

}  // namespace
}  // namespace lc::monitor
