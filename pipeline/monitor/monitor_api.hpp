#pragma once
// What `lightcone monitor` serves (docs/monitor.md), as plain functions of
// a request: the page, and a JSON API over render folders that only reads
// them (the journal, the event log, the frames).  No socket here: the
// server (monitor_command.cpp) hands each GET to MonitorApi::get, and the
// tests call it directly.
//
// Safe by construction: no request names a file.  A frame is asked for by
// folder number, shot and frame number, and its path is built here
// (store/frame_files.hpp); the shot must be one the folder holds, and the
// file must be a regular file inside the folder once links are followed.

#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <mutex>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "monitor/folder_list.hpp"
#include "monitor/parsed_cache.hpp"

namespace lc::monitor {

class FolderFile;

// An answer.  Its bytes are `body`, built in memory, or, when `file` is
// set, the bytes [file_offset, file_offset + file_length) of a file opened
// and checked (monitor/folder_file.hpp: regular, not a link), sent from
// the file as the client reads them (the server hands its descriptor to
// libmicrohttpd), never more than the size it had when opened.
struct Reply {
  // An answer built in memory (a file's is set after).
  Reply(int status = 200, std::string content_type = "application/json", std::string body = {})
      : status(status), content_type(std::move(content_type)), body(std::move(body)) {}

  int status;
  std::string content_type;
  std::string body;
  std::shared_ptr<FolderFile> file;
  std::uint64_t file_offset = 0, file_length = 0;
  // How many bytes the answer has.
  std::uint64_t size() const { return file ? file_length : body.size(); }
};

using Query = std::map<std::string, std::string>;

// The shots a render left in `dir` (a <shot>.journal or <shot>.events), by
// name.
std::vector<std::string> shots_in(const std::filesystem::path& dir);

class MonitorApi {
 public:
  // `dirs`: the render folders to show, or folders to find them under.
  // Throws std::invalid_argument naming one that is not a directory.  `tracer`: the lightcone binary, run for
  // the pixel inspector (monitor/pixel_trace.hpp); empty: no inspector.
  // `chart_script`: Chart.js's file (Debian's libjs-chart.js), served as
  // /chart.js when it exists.
  explicit MonitorApi(const std::vector<std::filesystem::path>& dirs, std::filesystem::path tracer = {},
                      std::filesystem::path chart_script = "/usr/share/javascript/chart.js/chart.min.js");

  // Answers GET `path` with `query`.  Never throws: what cannot be answered
  // is a 4xx reply whose JSON names why ({"error": "..."}), a failure to
  // read a 500.
  //   /                      the page
  //   /chart.js              the chart library
  //   /api/folders           the folders and their shots (render folders that appeared under them added)
  //   /api/status            ?folder=N&shot=S: counts, the run, its workers, errors, ETA
  //   /api/frames            ?folder=N&shot=S[&from=F][&count=C]: each finished frame's cost
  //   /api/events            ?folder=N&shot=S: the latest run's last events
  //   /api/frame.png         ?folder=N&shot=S&frame=F[&preview=1]: a frame's PNG
  //   /api/layer.png         ?folder=N&shot=S&frame=F&layer=L: a data layer of its EXR in false colour
  //   /api/trace             ?folder=N&shot=S&frame=F&x=I&y=J: the pixel's ray, as `lightcone trace` reports it
  //                          (one trace at a time: 429 while another runs; a pixel traced before answers from a cache)
  // Safe to call from several threads at once.
  Reply get(const std::string& path, const Query& query) const;

  // The folders shown so far: those given, then those found under them
  // (monitor/folder_list.hpp).
  std::vector<std::filesystem::path> folders() const { return folders_.current(); }
  // The journals and event logs parsed so far, kept between requests (for
  // the tests).
  const JournalCache& journals() const { return journals_; }
  const EventCache& event_logs() const { return events_; }

 private:
  Reply folders_reply() const;
  Reply status_reply(const Query& query) const;
  Reply frames_reply(const Query& query) const;
  Reply events_reply(const Query& query) const;
  Reply frame_png(const Query& query) const;
  Reply trace_reply(const Query& query) const;
  Reply layer_png(const Query& query) const;

  // The pixel inspector's traces: `busy` held while one runs, and the
  // latest replies by pixel (at most a bound, the oldest dropped first).
  struct TraceCache {
    std::mutex busy;
    mutable std::mutex mutex;
    std::map<std::string, std::string> replies;
    std::deque<std::string> order;
    std::optional<std::string> find(const std::string& key) const;
    void keep(const std::string& key, const std::string& reply);
  };

  FolderList folders_;  // canonical
  std::filesystem::path tracer_;
  std::filesystem::path chart_script_;
  mutable TraceCache traces_;
  mutable JournalCache journals_;
  mutable EventCache events_;
};

// The JSON error reply.
Reply error_reply(int status, const std::string& message);

// `reply` as an answer to a request whose Range header is `range` ("":
// none).  Inputs: any reply, in memory or a file; only a 200 is cut (a
// file's part is only its offset and length: nothing is read).  Output: `reply` itself
// when there is no range, its unit is not bytes or it does not parse (the
// header is then ignored, as RFC 9110 allows); a 206 holding the one range
// asked for (bytes=A-B, A- or -N, B past the end cut to it) with its
// Content-Range; a 416 with "bytes */<size>" when the range starts past
// the end or several ranges are asked for (never served: a list of many
// small ranges would make one request answer with the body many times).
struct RangedReply {
  Reply reply;
  std::string content_range;  // its Content-Range header ("" none)
};
RangedReply with_range(Reply reply, const std::string& range);

}  // namespace lc::monitor
