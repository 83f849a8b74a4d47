#pragma once
// The event log's file, DIR/<shot>.events: its lines and how they are read
// back (telemetry/event_log.hpp writes it; the monitor reads it).  Each line
// carries its check (store/checked_line.hpp): one cut short by a crash, or
// being written while a monitor reads, is skipped.  Lines:
//   lightcone-events 1
//   t=<unix s> event=run pid=<n> host=<name> ranks=<n> threads=<n> todo=<n> done=<n> size=<W>x<H> script=<path>
//              [cwd=<path> command=<argv joined by NUL>]            (what resumes the run)
//   t=<unix s> event=rank rank=<n> host=<name> threads=<n>          (an MPI worker joined)
//   t=<unix s> event=progress stored=<n> total=<n> rows=<done>/<all> rays=<n> core_seconds=<s> open=<f>,<f>,...
//              [held=<rank>:<sets>:<f>+<f>...,... [held_all=0]]      (an MPI farm: the workers holding sets;
//                                                                     held_all=0: more than fitted in 8 KiB)
//   t=<unix s> event=lost rank=<n> host=<name>                      (a worker that stopped answering)
//   t=<unix s> event=frame frame=<n> core_seconds=<s> rays=<n>       (a frame stored)
//   t=<unix s> event=error message=<percent-encoded text>
//   t=<unix s> event=end status=<done|interrupted|error> stored=<n>
// A run's lines follow its `run` line; a later `run` starts the next run.

#include <cstddef>
#include <deque>
#include <filesystem>
#include <istream>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lc::farm {

// The file's first line.
inline constexpr std::string_view events_header = "lightcone-events 1";
// The longest line a reader takes; a writer keeps its lines well under it.
inline constexpr std::size_t max_event_line = 16 * 1024;

// The file's name: DIR/<shot>.events.
std::filesystem::path events_file(const std::filesystem::path& dir, const std::string& shot);

// What a run's `run` line says.
struct RunStart {
  double time = 0.0;
  long pid = 0;
  std::string host;
  int ranks = 1, threads = 0;
  int todo = 0, done_before = 0;
  int width = 0, height = 0;
  std::string script;  // the shot script, absolute (the monitor's pixel inspector traces with it)
  // The render's command line (its argv) and the folder it ran in: what
  // resumes it, shown by the monitor to copy.  Empty in older logs.
  std::vector<std::string> command;
  std::string cwd;
};

// One worker's share of the work at a moment.
struct RankHolding {
  int rank = 0;
  int sets = 0;             // sets handed out and not returned
  std::vector<int> frames;  // the frames they belong to, ascending, each once
  bool operator==(const RankHolding&) const = default;
};

// "1:2:3+4,3:1:4" (rank:sets:frames, frames joined by '+'), the event log's
// `held` field, and back; a malformed entry is skipped when read.  Only
// ranks holding sets are written (one not listed holds none), and at most
// `max_chars` of them: an event line must stay under the log's limit on a
// farm of thousands of ranks.  `complete` says whether every one fitted.
std::string format_holdings(const std::vector<RankHolding>& holdings, std::size_t max_chars = 8192,
                            bool* complete = nullptr);
std::vector<RankHolding> parse_holdings(const std::string& text);

// One event as read back.
struct Event {
  double time = 0.0;
  std::string kind;                           // run, rank, progress, frame, lost, error, end
  std::map<std::string, std::string> fields;  // the rest, decoded
};

// The most workers (rank lines) and lost workers a summary holds.
inline constexpr std::size_t max_summary_ranks = 4096;

// What a monitor needs of an event log: the latest run and what happened
// in it.  Read a line at a time in bounded memory (a 100,000-frame film's
// log is read whole, but only the latest run's ranks, last progress and the
// last `keep` events are held).
struct EventSummary {
  std::optional<RunStart> run;              // the latest run, if any
  std::vector<Event> ranks;                 // its workers
  std::vector<int> lost;                    // its workers given up as lost
  std::optional<Event> progress;            // its latest progress line
  std::optional<Event> end;                 // how it ended, if it has
  std::deque<Event> recent;                 // its last `keep` events, oldest first
  std::vector<Event> errors;                // its errors (at most `keep`)
  int frames_stored = 0;                    // its frame lines
  int bad_lines = 0;                        // lines that failed their check or did not parse
};
// A log that is missing, or no regular file (a link, a FIFO), reads as
// an empty summary.
EventSummary read_events(const std::filesystem::path& file, std::size_t keep = 200);
// The same of a log's text (or of the lines appended to it since a read).
EventSummary read_events(std::istream& in, std::size_t keep = 200);

}  // namespace lc::farm
