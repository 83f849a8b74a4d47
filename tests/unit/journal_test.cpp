// The journal of finished frames: lines round-trip, a torn last line (cut
// anywhere) is ignored and cut off before the next append, a corrupt line
// in the middle is skipped without hiding the lines after it, someone
// else's file is refused.

#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>

#include "store/checked_line.hpp"
#include "store/content_hash.hpp"
#include "store/journal.hpp"
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
  f.cost = {.rays = 6144, .reused = 100 + n, .core_seconds = 1.25 * n, .star_seconds = 0.125, .finished = 1764000000 + n};
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
  EXPECT_EQ(f.cost.rays, 6144);
  EXPECT_EQ(f.cost.reused, 102);
  EXPECT_EQ(f.cost.core_seconds, 2.5);
  EXPECT_EQ(f.cost.star_seconds, 0.125);
  EXPECT_EQ(f.cost.finished, 1764000002);
  EXPECT_EQ(j.inputs.at("/shots/a b.lua"), "00000000000000aa");  // paths may hold spaces
  EXPECT_EQ(j.bad_lines, 0);
  EXPECT_FALSE(j.torn_tail);
  EXPECT_EQ(j.valid_bytes, journal_text(3).size());
}

// A 16-bit PNG and a window of the frame (render --png-depth, --region)
// are settings like the others: written only where they are not the
// default (an 8-bit whole frame's line reads as it always did), read back,
// and a frame made with them differs from one made without.
TEST(Journal, PngDepthAndWindowRoundTripAndAreSettings) {
  JournalFrame f = frame(4);
  const std::string plain = journal_frame_line(f);
  EXPECT_EQ(plain.find("png_depth"), std::string::npos);
  EXPECT_EQ(plain.find("region"), std::string::npos);
  f.settings.png_depth = PngDepth::sixteen;
  f.settings.window = {1024, 2048, 8192, 8192};
  const std::string line = journal_frame_line(f);
  EXPECT_NE(line.find(" png_depth=16 "), std::string::npos) << line;
  EXPECT_NE(line.find(" region=1024,2048,8192x8192 "), std::string::npos) << line;
  const JournalContents j = parse_journal(journal_header_line() + "\n" + line + "\n", "j");
  ASSERT_EQ(j.frames.size(), 1u);
  EXPECT_EQ(j.frames.at(4).settings, f.settings);
  EXPECT_FALSE(j.frames.at(4).settings == frame(4).settings);
  EXPECT_NE(f.settings.describe().find("the window at 1024,2048 of a 8192x8192 frame"), std::string::npos);
  EXPECT_NE(f.settings.describe().find("16-bit PNG"), std::string::npos);
  // Beside settings that differ in them, the defaults are said too.
  FrameSettings plain_settings = frame(4).settings;
  f.settings.delivery.camera = DeliveryCamera::dome;
  const std::string beside = plain_settings.describe(f.settings);
  EXPECT_NE(beside.find("8-bit PNG"), std::string::npos) << beside;
  EXPECT_NE(beside.find("(the whole frame)"), std::string::npos) << beside;
  EXPECT_NE(beside.find("through the shot's own camera"), std::string::npos) << beside;
  EXPECT_EQ(plain_settings.describe(), plain_settings.describe(plain_settings));
  EXPECT_EQ(plain_settings.describe().find("8-bit"), std::string::npos);
}

// A frame's look (what its PNG shows of its EXR) is recorded only where it
// is not the paper's, and read back to the bit: `lightcone develop` makes
// the PNG again from it.  It is not a setting: a frame developed with
// another look is still the render's frame.
TEST(Journal, ALookIsRecordedWhereThePngHasOne) {
  JournalFrame f = frame(4);
  EXPECT_EQ(journal_frame_line(f).find("look"), std::string::npos);
  f.look = Look{.exposure = -1.0 / 3.0, .view = View::gamut_safe, .bloom = 0.25};
  const std::string line = journal_frame_line(f);
  EXPECT_NE(line.find(" look=exposure:-0.3333333333333333,view:gamut_safe,bloom:0.25 #"), std::string::npos) << line;
  const JournalContents j = parse_journal(journal_header_line() + "\n" + line + "\n", "j");
  ASSERT_EQ(j.frames.size(), 1u);
  EXPECT_EQ(j.frames.at(4).look, f.look);
  EXPECT_EQ(j.frames.at(4).settings, frame(4).settings);
  // A look this lightcone cannot read makes the line a bad one, like any field.
  std::string bad = journal_frame_line(frame(5));
  bad = bad.substr(0, bad.rfind(" #")) + " look=view:agx";
  bad += " #" + to_hex(hash_bytes(bad));
  EXPECT_EQ(parse_journal(journal_header_line() + "\n" + bad + "\n", "j").frames.size(), 0u);
}

// Where a develop made the PNG through another look, the render's own is
// recorded beside it ("" for the paper's), so a later develop can shift
// from it; a line without it is the render's own look.
TEST(Journal, TheRendersOwnLookIsKeptBesideADevelopedOne) {
  JournalFrame f = frame(4);
  f.look = Look{.exposure = -33.7, .view = View::filmic};
  f.render_look = f.look;  // the same: not written
  EXPECT_EQ(journal_frame_line(f).find("render_look"), std::string::npos);
  EXPECT_FALSE(parse_journal(journal_header_line() + "\n" + journal_frame_line(f) + "\n", "j").frames.at(4).render_look);
  for (const Look rendered : {Look{.exposure = -34.2, .view = View::gamut_safe}, Look{}}) {
    f.render_look = rendered;
    const std::string line = journal_frame_line(f);
    EXPECT_NE(line.find(" look=exposure:-33.7,view:filmic render_look=" + look_text(rendered) + " #"), std::string::npos)
        << line;
    const JournalFrame back = parse_journal(journal_header_line() + "\n" + line + "\n", "j").frames.at(4);
    EXPECT_EQ(back.look, f.look);
    ASSERT_TRUE(back.render_look);
    EXPECT_EQ(back.rendered_look(), rendered);
  }
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

// A junk line of any length is a bad line, skipped without being held
// whole (issue #25: one of 600 MB made `render` and `cost` use ~2 GB); the
// lines after it still count, and the byte count past it stays exact.
TEST(Journal, AnOverlongLineIsSkippedAsABadLine) {
  const std::string junk(3 * max_journal_line, 'j');
  const std::string text = journal_text(1) + junk + "\n" + journal_frame_line(frame(1)) + "\n";
  const JournalContents j = parse_journal(text, "j");
  EXPECT_EQ(j.bad_lines, 1);
  EXPECT_EQ(j.frames.size(), 2u);
  EXPECT_EQ(j.valid_bytes, text.size());
  // Overlong and without its newline: a torn tail, cut off by the next writer.
  const JournalContents torn = parse_journal(journal_text(2) + junk, "j");
  EXPECT_TRUE(torn.torn_tail);
  EXPECT_EQ(torn.frames.size(), 2u);
  EXPECT_EQ(torn.valid_bytes, journal_text(2).size());
  // An overlong first line: not a journal.
  EXPECT_THROW(parse_journal(junk + "\n", "x.journal"), std::runtime_error);
}

// Numbers that are not finite or below 0 make the line bad, even under a
// matching check (std::from_chars reads "nan" and "inf").
TEST(Journal, NumbersThatAreNotFiniteOrNegativeMakeTheLineBad) {
  for (const char* bad : {"core_seconds=nan", "core_seconds=inf", "core_seconds=-1.000", "star_seconds=nan"}) {
    std::string line = journal_frame_line(frame(1));
    line = line.substr(0, line.rfind(" #"));
    const std::string key = std::string(bad).substr(0, std::string(bad).find('=') + 1);
    const auto at = line.find(key);
    line.replace(at, line.find(' ', at) - at, bad);
    const std::string text = journal_text(1) + line + " #" + to_hex(hash_bytes(line)) + "\n";
    const JournalContents j = parse_journal(text, "j");
    EXPECT_EQ(j.bad_lines, 1) << bad;
    EXPECT_EQ(j.frames.count(1), 0u) << bad;
  }
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

TEST(Journal, InputPartsRoundTripAndOlderLinesLackThem) {
  JournalFrame f = frame(4);
  f.parts = {"00000000000000aa", "00000000000000bb"};
  JournalFrame no_sky = frame(5);
  no_sky.parts.script = "00000000000000aa";
  const std::string text = journal_text(1) + journal_frame_line(f) + "\n" + journal_frame_line(no_sky) + "\n";
  const JournalContents j = parse_journal(text, "j");
  EXPECT_EQ(j.frames.at(4).parts, f.parts);
  EXPECT_EQ(j.frames.at(5).parts, no_sky.parts);
  EXPECT_EQ(j.frames.at(0).parts, InputParts{});  // a line without them (as older journals wrote)
  EXPECT_EQ(j.last_frame, 5);
  EXPECT_EQ(parse_journal(journal_text(3), "j").last_frame, 2);
  EXPECT_EQ(parse_journal(journal_header_line() + "\n", "j").last_frame, -1);
}

// A journal built line by line, as renders append to it.
struct JournalBuilder {
  std::string text = journal_header_line() + "\n";
  void input(const std::string& path, const std::string& hash) { text += journal_input_line(hash, path) + "\n"; }
  void frame(int n, const std::string& script, const std::string& sky = "", int width = 48) {
    JournalFrame f = ::lc::farm::frame(n);
    f.settings = {width, 32, 2, true, true};
    f.inputs = script;  // the whole hash, as far as these tests care
    f.parts = {script, sky};
    text += journal_frame_line(f) + "\n";
  }
  JournalContents contents() const { return parse_journal(text, "j"); }
};

// Frames 0..n-1 present, with the PNG sizes frame() records.
std::map<int, std::uintmax_t> present(std::initializer_list<int> frames) {
  std::map<int, std::uintmax_t> out;
  for (int f : frames) out[f] = 200 + static_cast<std::uintmax_t>(f);
  return out;
}

TEST(Journal, StaleFramesAreThoseOfAnEarlierScriptThanTheLatestRender) {
  // 0-4 rendered; the script changed; a --force render stopped after 0-1.
  JournalBuilder b;
  b.input("/s/shot.lua", "00000000000000a1");
  for (int f = 0; f < 5; ++f) b.frame(f, "00000000000000a1");
  b.input("/s/shot.lua", "00000000000000a2");
  b.frame(1, "00000000000000a2");
  b.frame(0, "00000000000000a2");
  const StaleFrames s = stale_frames(b.contents(), present({0, 1, 2, 3, 4}));
  EXPECT_EQ(s.earlier_script, (std::vector<int>{2, 3, 4}));
  EXPECT_TRUE(s.other_settings.empty());
  EXPECT_TRUE(s.unrecorded.empty());
  EXPECT_TRUE(s.any());
  // The script changed back and frame 3 was rendered again: now 0-1 are the odd ones.
  b.input("/s/shot.lua", "00000000000000a1");
  b.frame(3, "00000000000000a1");
  EXPECT_EQ(stale_frames(b.contents(), present({0, 1, 2, 3, 4})).earlier_script, (std::vector<int>{0, 1}));
}

TEST(Journal, SkyImagesTellAnEarlierVersionFromAnotherImage) {
  JournalBuilder b;
  b.input("/s/a.png", "00000000000000c1");
  b.input("/s/b.png", "00000000000000d1");
  b.frame(0, "00000000000000a1", "00000000000000c1");  // frames 0-1 under sky a, 2-3 under sky b
  b.frame(1, "00000000000000a1", "00000000000000c1");
  b.frame(2, "00000000000000a1", "00000000000000d1");
  b.frame(3, "00000000000000a1", "00000000000000d1");
  EXPECT_FALSE(stale_frames(b.contents(), present({0, 1, 2, 3})).any());
  // b.png changed and frame 2 was rendered again: 3 still shows the old b.
  b.input("/s/b.png", "00000000000000d2");
  b.frame(2, "00000000000000a1", "00000000000000d2");
  const StaleFrames s = stale_frames(b.contents(), present({0, 1, 2, 3}));
  EXPECT_EQ(s.earlier_sky, (std::vector<int>{3}));
  EXPECT_TRUE(s.earlier_script.empty());
}

TEST(Journal, OtherSettingsUnrecordedAndAbsentFrames) {
  JournalBuilder b;
  for (int f = 0; f < 6; ++f) b.frame(f, "00000000000000a1", "", 48);
  b.frame(4, "00000000000000a1", "", 96);  // the latest render: twice the size
  b.frame(5, "00000000000000a1", "", 96);
  auto frames = present({0, 1, 4, 5, 6, 7});
  frames[1] = 999;  // a PNG other than the one journalled (stopped between its rename and the journal)
  const StaleFrames s = stale_frames(b.contents(), frames);
  EXPECT_EQ(s.other_settings, (std::vector<int>{0}));
  EXPECT_EQ(s.unrecorded, (std::vector<int>{1, 6, 7}));  // 6 and 7 have no line at all
  // 2 and 3 are journalled but gone; as the old size, they are not holes of the new render.
  EXPECT_TRUE(s.absent.empty());
  b.frame(2, "00000000000000a1", "", 96);
  EXPECT_EQ(stale_frames(b.contents(), present({0, 4, 5})).absent, (std::vector<int>{2}));
  EXPECT_TRUE(stale_frames(b.contents(), present({4, 5})).absent.empty());  // outside the frames present
}

TEST(Journal, OlderLinesCompareByTheirWholeInputHash) {
  std::string text = journal_header_line() + "\n";
  const int order[] = {0, 1, 2, 1};  // lines without input parts; frame 1 again, from other inputs
  for (int k = 0; k < 4; ++k) {
    JournalFrame f = frame(order[k]);
    f.settings.adaptive = true;
    if (k == 3) f.inputs = "fedcba9876543210";
    text += journal_frame_line(f) + "\n";
  }
  const StaleFrames s = stale_frames(parse_journal(text, "j"), present({0, 1, 2}));
  EXPECT_EQ(s.earlier_script, (std::vector<int>{0, 2}));
}

TEST(Journal, WithoutAJournalNothingIsStale) {
  const StaleFrames s = stale_frames(JournalContents{}, present({0, 1, 2}));
  EXPECT_FALSE(s.any());
  EXPECT_TRUE(s.absent.empty());
}

TEST(Journal, MissingFileReadsEmpty) {
  test::ScratchDir dir;
  EXPECT_TRUE(read_journal(dir / "none.journal").frames.empty());
}

// What a frame cost: round-trips; a line without it (older journals) still
// counts, with the cost marked unrecorded.
TEST(Journal, CostRoundTripsAndOlderLinesLackIt) {
  JournalFrame old = frame(7);
  old.cost = {.rays = 5};
  const std::string text = journal_text(2) + journal_frame_line(old) + "\n";
  const JournalContents j = parse_journal(text, "j");
  EXPECT_TRUE(j.frames.at(1).cost.recorded());
  EXPECT_EQ(j.frames.at(1).cost.finished, 1764000001);
  EXPECT_FALSE(j.frames.at(7).cost.recorded());
  EXPECT_EQ(j.frames.at(7).cost.rays, 5);
  EXPECT_EQ(journal_frame_line(old).find("reused="), std::string::npos);
}

// Who made a frame and its wall time (the monitor's frame table): they
// round-trip, a node's name of any bytes (the list's comma, a space, '%')
// reads back, a list cut to max_listed_ranks keeps how many there were,
// and a malformed record makes the line bad as any malformed field does.
TEST(Journal, MakersAndWallTimeRoundTrip) {
  JournalFrame f = frame(3);
  f.cost.wall_seconds = 3.25;
  f.makers = {{{1, "node-a.farm"}, {2, "odd,name 100%"}, {7, ""}}, 3};
  const std::string line = journal_frame_line(f);
  EXPECT_NE(line.find(" wall_seconds=3.250 ranks=1,2,7 nodes=node-a.farm,odd%2Cname%20100%25, "), std::string::npos) << line;
  EXPECT_EQ(line.find("rank_count"), std::string::npos);  // every rank is listed
  JournalContents j = parse_journal(journal_text(0) + line + "\n", "j");
  ASSERT_EQ(j.frames.count(3), 1u);
  EXPECT_EQ(j.frames.at(3).cost.wall_seconds, 3.25);
  EXPECT_EQ(j.frames.at(3).makers, f.makers);
  // Cut: 16 of 40 ranks listed.
  f.makers.ranks.clear();
  for (int r = 1; r <= static_cast<int>(max_listed_ranks); ++r) f.makers.ranks.push_back({r, "n"});
  f.makers.count = 40;
  j = parse_journal(journal_text(0) + journal_frame_line(f) + "\n", "j");
  EXPECT_EQ(j.frames.at(3).makers, f.makers);
  EXPECT_NE(journal_frame_line(f).find(" rank_count=40"), std::string::npos);
  // A local farm's threads: rank 0 on this node.
  f.makers = {{{0, "here"}}, 1};
  j = parse_journal(journal_text(0) + journal_frame_line(f) + "\n", "j");
  EXPECT_EQ(j.frames.at(3).makers, f.makers);
}

TEST(Journal, MalformedMakersMakeTheLineBad) {
  const std::string base = journal_frame_line(frame(1));
  const std::string content = base.substr(0, base.rfind(" #"));
  for (const std::string fields : {" ranks=1,2 nodes=a", " ranks=1 nodes=a,b", " ranks=2,1 nodes=a,b", " ranks=1",
                                   " nodes=a", " ranks=1 nodes=a rank_count=1", " ranks=x nodes=a",
                                   " ranks=1 nodes=a rank_count=-3", " wall_seconds=-1", " wall_seconds=nan",
                                   " ranks=1,1 nodes=a,a"}) {
    const JournalContents j = parse_journal(journal_header_line() + "\n" + with_check(content + fields) + "\n", "j");
    EXPECT_EQ(j.frames.size(), 0u) << fields;
    EXPECT_EQ(j.bad_lines, 1) << fields;
  }
}

// A line as lightcone wrote it before it recorded who made a frame (a
// journal of an earlier release, written out literally): it reads, with
// its makers and wall time unrecorded, and a line written for it again
// (develop's) stays without them.
TEST(Journal, OlderLinesLackMakersAndWallTime) {
  const std::string old_line = with_check(
      "frame=4 size=48x32 supersample=1 layers=0 sampling=full inputs=0123456789abcdef script=0123456789abcdef "
      "exr=1004 png=204 rays=1536 reused=0 core_seconds=0.500 star_seconds=0.000 finished=1764000004");
  const JournalContents j = parse_journal(journal_header_line() + "\n" + old_line + "\n", "j");
  ASSERT_EQ(j.frames.count(4), 1u);
  const JournalFrame& f = j.frames.at(4);
  EXPECT_TRUE(f.cost.recorded());
  EXPECT_EQ(f.cost.wall_seconds, -1.0);
  EXPECT_TRUE(f.makers.ranks.empty());
  EXPECT_EQ(journal_frame_line(f), old_line);
}

}  // namespace
}  // namespace lc::farm
