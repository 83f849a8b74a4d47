#pragma once
// The journal of finished frames: DIR/<shot>.journal, a text file that is
// only ever appended to, one line per event, each line fsynced and ending
// in its own check ("... #<hash>").  A line cut short by a crash (no
// newline, or a check that does not match) is ignored, and the next writer
// cuts it off before appending, so a torn tail never hides the lines before
// it.  Lines:
//   lightcone-journal 1                                     (first line)
//   input hash=<16 hex> path=<file>                         (an input file's content as of a run)
//   frame=<n> size=<W>x<H> supersample=<N> layers=<0|1> sampling=<adaptive|full> [png_depth=16]
//     [region=<x0>,<y0>,<frame W>x<frame H>] [camera=<dome|360|ods>] [dome_tilt=<deg>]
//     [dome_elevation=<deg>] [separation=<M>] [sky_catalogue=kstars]
//     inputs=<16 hex> script=<16 hex> [sky=<16 hex>] exr=<bytes> png=<bytes> rays=<n>
//     reused=<n> core_seconds=<s> star_seconds=<s> finished=<unix seconds> [wall_seconds=<s>]
//     [ranks=<r>,<r>... nodes=<host>,<host>... [rank_count=<n>]] [look=<look_text>]
//     [render_look=<look_text>]
// A later frame line for the same frame supersedes an earlier one.  Lines
// of older journals lack sampling (full), script and sky, and what the
// frame cost beyond its rays; png_depth is written only for 16-bit PNGs,
// region only for a window of the frame (size is then the window's),
// camera only for a shot delivered through another camera (and its dome's
// tilt and elevation and ODS's separation only where not the defaults,
// sky_catalogue only under --sky kstars: lines of a plain dome read as they
// always did, and older lines are the defaults), look only where
// the PNG shows the EXR through another look than the paper's (image/look.hpp:
// what `lightcone develop` starts from), render_look only where a develop
// made the PNG through another look than the render did (the render's own,
// which develop's exposure shift and --reset start from; "" for the
// paper's).  wall_seconds, ranks and nodes (who made the frame, and how
// long it took: FrameMakers, FrameCost) are written since the monitor shows
// them; lines without them read as not recorded, and they are no setting:
// a frame's files do not depend on who rendered it.

#include <cstdint>
#include <cstddef>
#include <filesystem>
#include <istream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "store/frame_record.hpp"

namespace lc::farm {

struct JournalContents {
  std::map<int, JournalFrame> frames;            // the latest line of each frame
  int last_frame = -1;                           // the frame of the last frame line (the latest render's), -1: none
  std::map<std::string, std::string> inputs;     // path -> latest recorded hash
  int bad_lines = 0;                             // complete lines that failed their check (skipped)
  bool torn_tail = false;                        // the last line was cut short
  std::uintmax_t valid_bytes = 0;                // length up to the end of the last good line
};

// How the frames in a shot's directory relate to the latest render the
// journal records (its last frame line): frames made otherwise would be
// mixed into one sequence by encode or a contact sheet.  Each list is
// ascending.
struct StaleFrames {
  std::vector<int> other_settings;  // present, journalled with other settings than the latest render's
  std::vector<int> earlier_script;  // present, from an earlier version of the script or its modules
  std::vector<int> earlier_sky;     // present, with an earlier version of their sky image
  std::vector<int> unrecorded;      // present, but no journal line or a PNG of another size than it records
  std::vector<int> absent;          // journalled like the latest render, between the first and last present frame, no PNG
  // Any frame made otherwise (absent frames are holes, not stale).
  bool any() const { return !other_settings.empty() || !earlier_script.empty() || !earlier_sky.empty() || !unrecorded.empty(); }
};

// Compares the frames present (frame -> the size of its PNG) with the
// journal: a frame is stale when its line differs from the last frame
// line's in settings or script hash, or its sky hash is no longer any
// recorded input's latest hash.  Lines of older journals (without the input
// parts) compare by their whole input hash.  An empty journal (frames made
// elsewhere) finds nothing stale.
StaleFrames stale_frames(const JournalContents& journal, const std::map<int, std::uintmax_t>& png_sizes);

// The delivery as a frame line spells it (" camera=dome dome_tilt=15"):
// "" for the shot's own camera and sky.  Also the key the job's digest and
// the exposure meter take of it.
std::string delivery_fields(const Delivery& d);

// One line (without the newline) for each kind; with the check appended.
std::string journal_header_line();
std::string journal_frame_line(const JournalFrame& f);
std::string journal_input_line(const std::string& hash, const std::string& path);

// The longest journal line read: a frame line is ~300 bytes (and up to
// max_listed_ranks host names of at most 255 bytes), an input line a hash
// and a path.  A longer line is skipped as a bad line without
// being held whole (a junk line of 600 MB must not cost 600 MB).
inline constexpr std::size_t max_journal_line = 64 * 1024;

// Parses a journal's text, line by line in bounded memory.  Throws
// std::runtime_error naming `name` when the first complete line is not a
// lightcone journal header (someone else's file: better to stop than to
// append to it), or on a read error.
JournalContents parse_journal(std::istream& in, const std::string& name);
JournalContents parse_journal(const std::string& text, const std::string& name);

// Reads DIR/<shot>.journal; a missing file is an empty journal.  Throws
// naming it when it is no regular file (a link, a FIFO: see open_own_file
// in durable_file.hpp), or unreadable.
JournalContents read_journal(const std::filesystem::path& file);

// Appends lines durably.  The file is created (with its header) on the first
// append, so a render that finishes nothing leaves no journal behind.
class JournalWriter {
 public:
  // `valid_bytes` comes from read_journal: anything after it (a torn line)
  // is cut off before the first append.
  JournalWriter(std::filesystem::path file, std::uintmax_t valid_bytes);
  ~JournalWriter();
  JournalWriter(const JournalWriter&) = delete;
  JournalWriter& operator=(const JournalWriter&) = delete;

  // Writes one line (check added here) and fsyncs; throws
  // std::runtime_error naming the file (e.g. a full disk).  A failed append
  // leaves at most a torn line, which readers skip.
  void append(const std::string& line_with_check);

  const std::filesystem::path& file() const { return file_; }

 private:
  void open();
  std::filesystem::path file_;
  std::uintmax_t valid_bytes_;
  int fd_ = -1;
};

}  // namespace lc::farm
