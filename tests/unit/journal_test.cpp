// The journal of finished frames: lines round-trip, a torn last line (cut
// anywhere) is ignored and cut off before the next append, a corrupt line
// in the middle is skipped without hiding the lines after it, someone
// else's file is refused.

#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "farm/journal.hpp"
#include "scratch_dir.hpp"

namespace lc::farm {
namespace {

JournalFrame frame(int n) {
  JournalFrame f;
  f.frame = n;
  f.settings = {48, 32, 2, true, n % 2 == 0};  // adaptive sampling on even frames
  f.inputs = "0123456789abcdef";
  f.exr_bytes = 1000 + n;
  f.png_bytes = 200 + n;
  f.rays = 6144;
  return f;
}

std::string journal_text(int frames) {
  std::string text = journal_header_line() + "\n" + journal_input_line("00000000000000aa", "/shots/a b.lua") + "\n";
  for (int i = 0; i < frames; ++i) text += journal_frame_line(frame(i)) + "\n";
  return text;
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Journal, LinesRoundTrip) {
  const JournalContents j = parse_journal(journal_text(3), "j");
  ASSERT_EQ(j.frames.size(), 3u);
  const JournalFrame& f = j.frames.at(2);
  EXPECT_EQ(f.settings, (FrameSettings{48, 32, 2, true, true}));
  EXPECT_EQ(j.frames.at(1).settings, (FrameSettings{48, 32, 2, true, false}));
  EXPECT_EQ(f.inputs, "0123456789abcdef");
  EXPECT_EQ(f.exr_bytes, 1002u);
  EXPECT_EQ(f.png_bytes, 202u);
  EXPECT_EQ(f.rays, 6144);
  EXPECT_EQ(j.inputs.at("/shots/a b.lua"), "00000000000000aa");  // paths may hold spaces
  EXPECT_EQ(j.bad_lines, 0);
  EXPECT_FALSE(j.torn_tail);
  EXPECT_EQ(j.valid_bytes, journal_text(3).size());
}

TEST(Journal, EmptyTextIsAnEmptyJournal) {
  const JournalContents j = parse_journal("", "j");
  EXPECT_TRUE(j.frames.empty());
  EXPECT_EQ(j.valid_bytes, 0u);
}

// Cut the text at every byte of its last line: the first two frames always
// survive, the third only when its line is complete.
TEST(Journal, TornLastLineAtEveryByteIsIgnored) {
  const std::string full = journal_text(3);
  const std::size_t last_start = journal_text(2).size();
  for (std::size_t cut = last_start; cut < full.size(); ++cut) {
    const JournalContents j = parse_journal(full.substr(0, cut), "j");
    EXPECT_EQ(j.frames.size(), 2u) << "cut at " << cut;
    EXPECT_EQ(j.valid_bytes, last_start) << "cut at " << cut;
    EXPECT_EQ(j.torn_tail, cut > last_start) << "cut at " << cut;
  }
  EXPECT_EQ(parse_journal(full, "j").frames.size(), 3u);
}

TEST(Journal, TornHeaderIsAnEmptyJournal) {
  const JournalContents j = parse_journal(journal_header_line().substr(0, 7), "j");
  EXPECT_TRUE(j.frames.empty());
  EXPECT_TRUE(j.torn_tail);
  EXPECT_EQ(j.valid_bytes, 0u);
}

TEST(Journal, CorruptMiddleLineIsSkipped) {
  std::string text = journal_text(3);
  const std::size_t second = journal_text(1).size();
  text[second + 8] = text[second + 8] == '1' ? '7' : '1';  // flip a digit of frame 1's line
  const JournalContents j = parse_journal(text, "j");
  EXPECT_EQ(j.bad_lines, 1);
  EXPECT_EQ(j.frames.count(0), 1u);
  EXPECT_EQ(j.frames.count(1), 0u);
  EXPECT_EQ(j.frames.count(2), 1u);
  EXPECT_EQ(j.valid_bytes, text.size());
}

TEST(Journal, LaterLineSupersedesEarlier) {
  JournalFrame again = frame(1);
  again.settings.width = 96;
  const std::string text = journal_text(2) + journal_frame_line(again) + "\n";
  EXPECT_EQ(parse_journal(text, "j").frames.at(1).settings.width, 96);
}

TEST(Journal, ForeignFileIsRefused) {
  EXPECT_THROW(parse_journal("hello world\n", "notes.txt"), std::runtime_error);
  try {
    parse_journal("frame=1 size=1x1\n", "x.journal");
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("x.journal is not a lightcone journal"), std::string::npos) << e.what();
  }
}

TEST(Journal, WriterCreatesLazilyAndCutsTornTail) {
  test::ScratchDir dir;
  const auto file = dir / "s.journal";
  {
    JournalWriter w(file, 0);
    EXPECT_FALSE(std::filesystem::exists(file));  // nothing appended, nothing created
    w.append(journal_frame_line(frame(0)));
  }
  // Simulate a crash half-way through the next line.
  {
    std::ofstream out(file, std::ios::app | std::ios::binary);
    out << journal_frame_line(frame(1)).substr(0, 20);
  }
  JournalContents j = read_journal(file);
  ASSERT_TRUE(j.torn_tail);
  ASSERT_EQ(j.frames.size(), 1u);
  {
    JournalWriter w(file, j.valid_bytes);
    w.append(journal_frame_line(frame(2)));
  }
  j = read_journal(file);
  EXPECT_FALSE(j.torn_tail);
  EXPECT_EQ(j.bad_lines, 0);
  EXPECT_EQ(j.frames.size(), 2u);
  EXPECT_EQ(j.frames.count(2), 1u);
  EXPECT_EQ(slurp(file), journal_header_line() + "\n" + journal_frame_line(frame(0)) + "\n" +
                             journal_frame_line(frame(2)) + "\n");
}

TEST(Journal, MissingFileReadsEmpty) {
  test::ScratchDir dir;
  EXPECT_TRUE(read_journal(dir / "none.journal").frames.empty());
}

}  // namespace
}  // namespace lc::farm
