#include "monitor/monitor_api.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <cstdio>
#include <stdexcept>
#include <string_view>

#include <unistd.h>

#include <fmt/format.h>

#include "core/json.hpp"
#include "store/durable_file.hpp"
#include "store/event_file.hpp"
#include "store/frame_files.hpp"
#include "store/journal.hpp"
#include "image/image_io.hpp"
#include "monitor/folder_file.hpp"
#include "monitor/layer_picture.hpp"
#include "monitor/pixel_trace.hpp"
#include "render/layers.hpp"
#include "monitor_page.hpp"  // generated from monitor/page.html (pipeline/CMakeLists.txt)
#include "store/frame_sequence.hpp"

namespace lc::monitor {

namespace fs = std::filesystem;

namespace {

// A run whose log has said nothing for this long without an end line has
// stopped (killed, or its node lost): it writes progress every 2 s.
constexpr double silent_after_seconds = 15.0;
constexpr int max_frames_per_reply = 10000;
// The largest file read into memory (a frame's EXR for its layer picture,
// that picture's PNG): one request must not hold more.  A file served as
// it is (a frame's PNG, the chart library) is sent from disk whatever its
// size.  A 16-bit 8K frame's PNG is ~200 MB.
constexpr std::size_t max_served_bytes = 512u << 20;
// The pixel traces kept, so that asking again for a pixel (the page's
// user clicking about) costs no new trace.
constexpr std::size_t max_cached_traces = 64;

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

struct BadRequest : std::runtime_error {
  BadRequest(int status, const std::string& message) : std::runtime_error(message), status(status) {}
  int status;
};

// A whole number in [lo, hi] from a query parameter.
long number_param(const Query& q, const char* name, long lo, long hi, std::optional<long> fallback = std::nullopt) {
  const auto it = q.find(name);
  if (it == q.end()) {
    if (fallback) return *fallback;
    throw BadRequest(400, fmt::format("missing parameter '{}'", name));
  }
  long v = 0;
  const std::string& s = it->second;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || v < lo || v > hi)
    throw BadRequest(400, fmt::format("parameter '{}' must be a whole number from {} to {}", name, lo, hi));
  return v;
}

std::string json_text(const std::string& s) { return json_string(s); }

std::string json_list(const std::vector<int>& v) {
  std::string out = "[";
  for (std::size_t k = 0; k < v.size(); ++k) out += (k ? "," : "") + std::to_string(v[k]);
  return out + "]";
}

std::string shell_word(const std::string& word);

// An event as JSON; a run's command (its arguments joined by NUL) as the
// shell line of its words, as the page shows it.
std::string event_json(const farm::Event& e) {
  std::string out = fmt::format("{{\"t\": {}, \"event\": {}", json_number(e.time), json_text(e.kind));
  for (const auto& [k, v] : e.fields) {
    std::string text = v;
    if (e.kind == "run" && k == "command") {
      text.clear();
      std::istringstream args(v);
      for (std::string arg; std::getline(args, arg, '\0');) text += (text.empty() ? "" : " ") + shell_word(arg);
    }
    out += fmt::format(", {}: {}", json_text(k), json_text(text));
  }
  return out + "}";
}

// The bytes of `p` (no link in its last component: the callers resolve
// links first), if it is a regular file of at most max_served_bytes.
std::string read_file(const fs::path& p) {
  const FolderFile file(p);
  if (file.missing() || file.refused()) throw BadRequest(404, fmt::format("cannot read {}", p.filename().string()));
  try {
    return file.read_all(max_served_bytes);
  } catch (const std::runtime_error& e) {
    throw BadRequest(413, fmt::format("{} {}", p.filename().string(), e.what()));
  }
}

// `p` (no link in its last component: the callers resolve links first) as
// an answer sent from the file itself as the client reads it (nothing of it
// held in memory, so no bound on its size), if it is a regular file: the
// file opened here is the one sent, at the size it had then.
Reply file_reply(const fs::path& p, const char* content_type) {
  auto file = std::make_shared<FolderFile>(p);
  if (file->missing() || file->refused()) throw BadRequest(404, fmt::format("cannot read {}", p.filename().string()));
  Reply reply(200, content_type);
  reply.file_length = file->size();
  reply.file = std::move(file);
  return reply;
}

// The journal of `shot` in `dir` (canonical), read only if it is a regular
// file of the folder that begins as lightcone's journals do: a link, a FIFO,
// a device or someone else's file is refused without a word of what it
// holds.  No journal: an empty one.  Parsed through `cache`: only what was
// appended since the last request is read.
std::shared_ptr<const farm::JournalContents> journal_of(JournalCache& cache, const fs::path& dir, const std::string& shot) {
  const std::string name = shot + ".journal";
  const FolderFile file(dir / name);
  if (file.missing()) return std::make_shared<const farm::JournalContents>();
  if (file.refused()) throw BadRequest(403, fmt::format("{} {}", name, file.why()));
  // A journal cut short in its first line (a crash as it was created) is a
  // prefix of the header; anything else is not lightcone's.
  const std::string header = farm::journal_header_line() + "\n";
  const std::string head = file.head(header.size());
  if (header.compare(0, head.size(), head) != 0)
    throw BadRequest(422, fmt::format("{} is not a lightcone journal: not read", name));
  try {
    return cache.read(file, (dir / name).string());
  } catch (const std::exception&) {
    throw std::runtime_error(fmt::format("cannot read {}", name));
  }
}

// The event log of `shot` in `dir`, on the same terms as journal_of (its
// lines that fail their check are only counted, never shown): the latest
// run and its last EventFormat::keep events.
std::shared_ptr<const farm::EventSummary> events_of(EventCache& cache, const fs::path& dir, const std::string& shot) {
  const fs::path path = farm::events_file(dir, shot);
  const FolderFile file(path);
  if (file.missing()) return std::make_shared<const farm::EventSummary>();
  if (file.refused()) throw BadRequest(403, fmt::format("{} {}", path.filename().string(), file.why()));
  try {
    return cache.read(file, path.string());
  } catch (const std::exception&) {
    throw std::runtime_error(fmt::format("cannot read {}", path.filename().string()));
  }
}

// `word` as one word of a POSIX shell's command line: as it is when it
// holds nothing the shell reads specially, else in single quotes.
std::string shell_word(const std::string& word) {
  const bool plain = !word.empty() && std::all_of(word.begin(), word.end(), [](unsigned char ch) {
    return std::isalnum(ch) || std::string_view("_./=:,+-@%").find(static_cast<char>(ch)) != std::string_view::npos;
  });
  if (plain) return word;
  std::string out = "'";
  for (char ch : word) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

// The command that resumes the run `r` (the same command in the same
// folder: docs/monitor.md), as JSON; null when its log does not say (an
// older lightcone).  An MPI run's launcher is not in its command line:
// `mpirun -n <ranks>` stands for it.
std::string resume_json(const farm::RunStart& r) {
  if (r.command.empty()) return "null";
  std::string line = "cd " + shell_word(r.cwd.empty() ? "." : r.cwd) + " &&";
  if (r.ranks > 1) line += fmt::format(" mpirun -n {}", r.ranks);
  for (const std::string& arg : r.command) line += " " + shell_word(arg);
  return json_text(line);
}

}  // namespace

Reply error_reply(int status, const std::string& message) {
  return {status, "application/json", fmt::format("{{\"error\": {}}}\n", json_text(message))};
}

RangedReply with_range(Reply reply, const std::string& range) {
  const auto trim = [](std::string_view v) {
    while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
    while (!v.empty() && (v.back() == ' ' || v.back() == '\t')) v.remove_suffix(1);
    return v;
  };
  std::string_view r = trim(range);
  if (reply.status != 200 || r.substr(0, 6) != "bytes=") return {std::move(reply), ""};
  r = trim(r.substr(6));
  const std::uint64_t size = reply.size();
  const auto refuse = [&](const std::string& why) {
    return RangedReply{error_reply(416, why), fmt::format("bytes */{}", size)};
  };
  if (r.find(',') != std::string_view::npos) return refuse("several ranges in one request are not served");
  const std::size_t dash = r.find('-');
  if (dash == std::string_view::npos) return {std::move(reply), ""};
  // A number of the header; past 2^64: the largest (a range that far starts
  // past any body, or ends at its end).  nullopt: not a number.
  const auto number = [&](std::string_view v) -> std::optional<std::uint64_t> {
    v = trim(v);
    std::uint64_t n = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
    if (v.empty() || end != v.data() + v.size()) return std::nullopt;
    return ec == std::errc::result_out_of_range ? UINT64_MAX : n;
  };
  std::uint64_t first = 0, last = 0;
  if (trim(r.substr(0, dash)).empty()) {  // the last N bytes
    const auto n = number(r.substr(dash + 1));
    if (!n) return {std::move(reply), ""};
    if (*n == 0 || size == 0) return refuse("the range asks for no bytes");
    first = size - std::min(*n, size);
    last = size - 1;
  } else {
    const auto a = number(r.substr(0, dash));
    if (!a) return {std::move(reply), ""};
    std::optional<std::uint64_t> b = UINT64_MAX;
    if (!trim(r.substr(dash + 1)).empty()) b = number(r.substr(dash + 1));
    if (!b || *b < *a) return {std::move(reply), ""};
    if (*a >= size) return refuse(fmt::format("the range starts past the answer's {} bytes", size));
    first = *a;
    last = std::min(*b, size - 1);
  }
  reply.status = 206;
  if (reply.file) {
    reply.file_offset += first;
    reply.file_length = last - first + 1;
  } else {
    reply.body = reply.body.substr(first, last - first + 1);
  }
  return {std::move(reply), fmt::format("bytes {}-{}/{}", first, last, size)};
}

std::vector<std::string> shots_in(const fs::path& dir) {
  std::vector<std::string> shots;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string ext = e.path().extension().string();
    // Not followed through a link: a link's target is not the render's.
    if ((ext == ".journal" || ext == ".events") && e.symlink_status(ec).type() == fs::file_type::regular)
      shots.push_back(e.path().stem().string());
  }
  std::sort(shots.begin(), shots.end());
  shots.erase(std::unique(shots.begin(), shots.end()), shots.end());
  return shots;
}

namespace {

// The canonical folders of `dirs`; throws std::invalid_argument naming one
// that is not a directory, or when there are none.
std::vector<fs::path> canonical_folders(const std::vector<fs::path>& dirs) {
  std::vector<fs::path> out;
  for (const fs::path& d : dirs) {
    std::error_code ec;
    if (!fs::is_directory(d, ec))
      throw std::invalid_argument(fmt::format("{}: not a directory (give the folders renders write to: render --out, "
                                              "or a folder they are in)",
                                              d.string()));
    out.push_back(fs::canonical(d));
  }
  if (out.empty()) throw std::invalid_argument("give at least one render folder");
  return out;
}

}  // namespace

MonitorApi::MonitorApi(const std::vector<fs::path>& dirs, fs::path tracer, fs::path chart_script)
    : folders_(canonical_folders(dirs)), tracer_(std::move(tracer)), chart_script_(std::move(chart_script)) {}

Reply MonitorApi::get(const std::string& path, const Query& query) const {
  try {
    if (path == "/" || path == "/index.html") return {200, "text/html; charset=utf-8", std::string(monitor_page)};
    if (path == "/chart.js") {
      std::error_code ec;
      const fs::path chart = fs::canonical(chart_script_, ec);  // Debian's names are links
      if (ec || !fs::is_regular_file(chart, ec))
        return error_reply(404, fmt::format("{} is missing: install Debian's libjs-chart.js for the cost chart",
                                            chart_script_.string()));
      return file_reply(chart, "text/javascript");
    }
    if (path == "/api/folders") return folders_reply();
    if (path == "/api/status") return status_reply(query);
    if (path == "/api/frames") return frames_reply(query);
    if (path == "/api/events") return events_reply(query);
    if (path == "/api/frame.png") return frame_png(query);
    if (path == "/api/trace") return trace_reply(query);
    if (path == "/api/layer.png") return layer_png(query);
    return error_reply(404, fmt::format("no such page: {}", path.substr(0, 200)));
  } catch (const BadRequest& e) {
    return error_reply(e.status, e.what());
  } catch (const std::exception& e) {
    return error_reply(500, e.what());
  }
}

Reply MonitorApi::folders_reply() const {
  const std::vector<fs::path> dirs = folders_.search();
  std::string out = "{\"folders\": [";
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    std::string shots;
    for (const std::string& s : shots_in(dirs[i])) shots += (shots.empty() ? "" : ", ") + json_text(s);
    out += fmt::format("{}{{\"id\": {}, \"path\": {}, \"shots\": [{}]}}", i ? ", " : "", i, json_text(dirs[i].string()),
                       shots);
  }
  std::string names;
  for (const LayerSpec& l : layers) names += (names.empty() ? "" : ", ") + json_text(std::string(l.name));
  return {200, "application/json", out + "], \"layers\": [" + names + "]}\n"};
}

std::optional<std::string> MonitorApi::TraceCache::find(const std::string& key) const {
  // Input: a pixel's key (the frame as its journal line records it); a copy,
  // as another thread may drop the kept one meanwhile.
  const std::lock_guard lock(mutex);
  const auto it = replies.find(key);
  if (it == replies.end()) return std::nullopt;
  return it->second;
}

void MonitorApi::TraceCache::keep(const std::string& key, const std::string& reply) {
  // Input: a trace's reply; the oldest kept is dropped beyond the bound.
  const std::lock_guard lock(mutex);
  if (!replies.emplace(key, reply).second) return;
  order.push_back(key);
  if (order.size() > max_cached_traces) {
    replies.erase(order.front());
    order.pop_front();
  }
}

namespace {

// The folder and shot a request names: the folder by its number, the shot
// one that folder holds (so a name never reaches a path unchecked).
std::pair<fs::path, std::string> folder_and_shot(const std::vector<fs::path>& dirs, const Query& q) {
  const long folder = number_param(q, "folder", 0, static_cast<long>(dirs.size()) - 1);
  const auto it = q.find("shot");
  if (it == q.end()) throw BadRequest(400, "missing parameter 'shot'");
  const fs::path& dir = dirs[static_cast<std::size_t>(folder)];
  const std::vector<std::string> shots = shots_in(dir);
  if (std::find(shots.begin(), shots.end(), it->second) == shots.end())
    throw BadRequest(404, fmt::format("folder {} holds no render of a shot called '{}'", folder, it->second.substr(0, 100)));
  return {dir, it->second};
}

// The file of a frame, links followed, if it is a regular file inside the
// folder `dir` (canonical): 404 when there is none, 403 when it links out.
fs::path frame_file(const fs::path& dir, const fs::path& file, long frame, const std::string& shot) {
  std::error_code ec;
  if (!fs::is_regular_file(file, ec))
    throw BadRequest(404, fmt::format("frame {} of '{}' has no {}", frame, shot, file.extension() == ".exr" ? "EXR" : "PNG"));
  const fs::path real = fs::canonical(file, ec);
  const auto [end, ignored] = std::mismatch(dir.begin(), dir.end(), real.begin(), real.end());
  if (ec || end != dir.end())
    throw BadRequest(403, fmt::format("frame {} of '{}' links outside the folder: not served", frame, shot));
  return real;
}

}  // namespace

namespace {

// The frames the latest run stored per second of wall time lately: over
// its last frame_rate_window frames as the log's recent events hold them
// (from the run's start while it has stored no more: the shot's loading is
// the run's), or, when they hold fewer than two of them (slow frames among
// many progress lines), over the whole run to its last event.  nullopt
// before a frame, or with no time between.
std::optional<double> frames_per_second(const farm::EventSummary& ev) {
  constexpr std::size_t frame_rate_window = 20;
  if (!ev.run || ev.frames_stored == 0) return std::nullopt;
  std::vector<double> times;
  for (const farm::Event& e : ev.recent)
    if (e.kind == "frame") times.push_back(e.time);
  if (times.size() == static_cast<std::size_t>(ev.frames_stored)) times.insert(times.begin(), ev.run->time);
  if (times.size() > frame_rate_window + 1) times.erase(times.begin(), times.end() - (frame_rate_window + 1));
  if (times.size() >= 3 || (times.size() == 2 && times.front() == ev.run->time)) {
    if (times.back() > times.front()) return static_cast<double>(times.size() - 1) / (times.back() - times.front());
    return std::nullopt;
  }
  const double last = ev.recent.empty() ? ev.run->time : ev.recent.back().time;
  if (last <= ev.run->time) return std::nullopt;
  return ev.frames_stored / (last - ev.run->time);
}

}  // namespace

Reply MonitorApi::status_reply(const Query& q) const {
  const auto [dir, shot] = folder_and_shot(folders_.current(), q);
  const auto journal_ptr = journal_of(journals_, dir, shot);
  const farm::JournalContents& journal = *journal_ptr;
  std::map<int, std::uintmax_t> png_sizes;
  const auto sequences = find_frame_sequences(dir);
  if (const auto seq = sequences.find(shot); seq != sequences.end())
    for (std::size_t k = 0; k < seq->second.frames.size(); ++k) {
      std::error_code ec;
      const auto size = fs::file_size(seq->second.files[k], ec);
      if (!ec) png_sizes[seq->second.frames[k]] = size;
    }
  const farm::StaleFrames stale = farm::stale_frames(journal, png_sizes);
  int done = 0;
  double core_seconds = 0.0;
  std::vector<std::pair<std::int64_t, int>> by_time;
  for (const auto& [f, jf] : journal.frames) {
    const auto png = png_sizes.find(f);
    if (png != png_sizes.end() && png->second == jf.png_bytes) ++done;
    if (jf.cost.recorded()) core_seconds += jf.cost.core_seconds + jf.cost.star_seconds;
    by_time.emplace_back(jf.cost.finished, f);
  }
  std::sort(by_time.rbegin(), by_time.rend());
  std::vector<int> latest;
  for (std::size_t k = 0; k < by_time.size() && k < 8; ++k) latest.push_back(by_time[k].second);
  const std::size_t stale_count = stale.other_settings.size() + stale.earlier_script.size() + stale.earlier_sky.size() +
                                  stale.unrecorded.size();

  const auto events = events_of(events_, dir, shot);
  const farm::EventSummary& ev = *events;
  std::string run = "null";
  std::vector<int> in_flight;
  int to_do = 0;
  if (ev.run) {
    const farm::RunStart& r = *ev.run;
    const double last = ev.recent.empty() ? r.time : ev.recent.back().time;
    std::string state = ev.end ? ev.end->fields.count("status") ? ev.end->fields.at("status") : "done"
                               : (now_seconds() - last > silent_after_seconds ? "stopped" : "running");
    int threads = r.threads;
    // Each worker's state: lost (the master gave up on it), else the run's
    // while it is not running, else working or waiting by what it holds.
    const auto held = ev.progress && ev.progress->fields.count("held") ? farm::parse_holdings(ev.progress->fields.at("held"))
                                                                       : std::vector<farm::RankHolding>{};
    // A worker not listed holds nothing, unless the list was cut short.
    const bool held_all = !(ev.progress && ev.progress->fields.count("held_all"));
    std::string workers;
    for (const farm::Event& w : ev.ranks) {
      const int t = std::atoi(w.fields.count("threads") ? w.fields.at("threads").c_str() : "0");
      const int rank = std::atoi(w.fields.count("rank") ? w.fields.at("rank").c_str() : "0");
      threads += t;
      farm::RankHolding h{rank, 0, {}};
      for (const farm::RankHolding& x : held)
        if (x.rank == rank) h = x;
      const bool lost = std::find(ev.lost.begin(), ev.lost.end(), rank) != ev.lost.end();
      const std::string rank_state = lost                ? "lost"
                                     : state != "running" ? state
                                     : h.sets > 0         ? "working"
                                     : held_all           ? "waiting"
                                                          : "running";  // not in a list cut short: unknown
      workers += fmt::format("{}{{\"rank\": {}, \"host\": {}, \"threads\": {}, \"state\": {}, \"sets\": {}, "
                             "\"frames\": {}}}",
                             workers.empty() ? "" : ", ", rank, json_text(w.fields.count("host") ? w.fields.at("host") : ""),
                             t, json_text(rank_state), h.sets, json_list(h.frames));
    }
    if (state == "running" && ev.progress && ev.progress->fields.count("open")) {
      std::istringstream open(ev.progress->fields.at("open"));
      for (std::string f; std::getline(open, f, ',');)
        if (!f.empty()) in_flight.push_back(std::atoi(f.c_str()));
    }
    // The run's frames not stored, whatever its state: an interrupted run
    // left them for the same command to resume.
    to_do = std::max(0, r.todo - ev.frames_stored);
    const std::optional<double> rate = frames_per_second(ev);
    const std::string per_minute = rate ? json_number(*rate * 60.0) : "null";
    const std::string eta = state == "running" && rate ? json_number(to_do / *rate) : "null";
    // What ended the run, named: the ranks it lost (a killed worker, a node
    // gone: the launcher then ends the job), else its error, else a signal.
    std::string ended_by = "null";
    if (ev.end && state != "done") {
      std::string lost;
      for (const int rank : ev.lost) {
        std::string host;
        for (const farm::Event& w : ev.ranks)
          if (w.fields.count("rank") && std::atoi(w.fields.at("rank").c_str()) == rank && w.fields.count("host"))
            host = w.fields.at("host");
        lost += fmt::format("{}rank {}{}", lost.empty() ? "" : ", ", rank, host.empty() ? "" : " on " + host);
      }
      ended_by = json_text(!lost.empty()         ? lost + " stopped answering (lost)"
                           : !ev.errors.empty()  ? ev.errors.back().fields.count("message") ? ev.errors.back().fields.at("message") : "an error"
                           : state == "interrupted" ? "a signal: Ctrl-C, a kill, or the launcher ending the job"
                                                    : state);
    }
    run = fmt::format(
        "{{\"state\": {}, \"started\": {}, \"last_event\": {}, \"pid\": {}, \"host\": {}, \"ranks\": {}, \"threads\": {}, "
        "\"todo\": {}, \"stored\": {}, \"frames_per_minute\": {}, \"eta_seconds\": {}, \"workers\": [{}], "
        "\"size\": [{}, {}], \"resume\": {}, \"ended_by\": {}}}",
        json_text(state), json_number(r.time), json_number(last), r.pid, json_text(r.host), r.ranks, threads, r.todo,
        ev.frames_stored, per_minute, eta, workers, r.width, r.height, resume_json(r), ended_by);
  }
  std::string errors;
  for (const farm::Event& e : ev.errors)
    errors += fmt::format("{}{{\"t\": {}, \"message\": {}}}", errors.empty() ? "" : ", ", json_number(e.time),
                          json_text(e.fields.count("message") ? e.fields.at("message") : ""));
  return {200, "application/json",
          fmt::format("{{\"folder\": {}, \"shot\": {}, \"frames\": {{\"done\": {}, \"in_flight\": {}, \"to_do\": {}, "
                      "\"stale\": {}}}, \"core_seconds\": {}, \"latest\": {}, \"run\": {}, \"errors\": [{}], "
                      "\"bad_journal_lines\": {}, \"bad_event_lines\": {}}}\n",
                      number_param(q, "folder", 0, 1L << 30), json_text(shot), done, json_list(in_flight), to_do, stale_count,
                      json_number(core_seconds), json_list(latest), run, errors, journal.bad_lines, ev.bad_lines)};
}

Reply MonitorApi::frames_reply(const Query& q) const {
  const auto [dir, shot] = folder_and_shot(folders_.current(), q);
  const long from = number_param(q, "from", 0, 10'000'000, 0);
  const long count = number_param(q, "count", 1, max_frames_per_reply, 1000);
  const long since = number_param(q, "since", 0, 1L << 40, 0);
  const auto journal_ptr = journal_of(journals_, dir, shot);
  const farm::JournalContents& journal = *journal_ptr;
  std::string out;
  long n = 0;
  std::string next = "null";  // where to go on from when `count` cut the answer short
  for (auto it = journal.frames.lower_bound(static_cast<int>(from)); it != journal.frames.end(); ++it) {
    const farm::JournalFrame& jf = it->second;
    if (jf.cost.finished < since) continue;
    if (n == count) {
      next = std::to_string(jf.frame);
      break;
    }
    // Who made it and its wall time, where its line records them (null,
    // [] in older journals).
    std::vector<int> ranks;
    std::string nodes;
    for (const farm::FrameMakers::Rank& r : jf.makers.ranks) {
      ranks.push_back(r.rank);
      if (!nodes.empty()) nodes += ',';
      nodes += json_text(r.node);
    }
    out += fmt::format("{}{{\"frame\": {}, \"core_seconds\": {}, \"rays\": {}, \"finished\": {}, \"wall_seconds\": {}, "
                       "\"ranks\": {}, \"nodes\": [{}], \"rank_count\": {}}}",
                       n ? ", " : "", jf.frame,
                       jf.cost.recorded() ? json_number(jf.cost.core_seconds + jf.cost.star_seconds) : "null",
                       jf.cost.rays, jf.cost.finished,
                       jf.cost.wall_seconds >= 0.0 ? json_number(jf.cost.wall_seconds) : "null", json_list(ranks), nodes,
                       jf.makers.count);
    ++n;
  }
  return {200, "application/json",
          fmt::format("{{\"total\": {}, \"frames\": [{}], \"next\": {}}}\n", journal.frames.size(), out, next)};
}

Reply MonitorApi::events_reply(const Query& q) const {
  const auto [dir, shot] = folder_and_shot(folders_.current(), q);
  const auto events = events_of(events_, dir, shot);
  const farm::EventSummary& ev = *events;
  std::string out;
  for (const farm::Event& e : ev.recent) out += (out.empty() ? "" : ", ") + event_json(e);
  return {200, "application/json", fmt::format("{{\"events\": [{}]}}\n", out)};
}

Reply MonitorApi::frame_png(const Query& q) const {
  const auto [dir, shot] = folder_and_shot(folders_.current(), q);
  const long frame = number_param(q, "frame", 0, 99'999'999);
  const bool preview = number_param(q, "preview", 0, 1, 0) == 1;
  const fs::path real =
      frame_file(dir, farm::frame_path(preview ? dir / "preview" : dir, shot, static_cast<int>(frame), "png"), frame, shot);
  return file_reply(real, "image/png");
}

Reply MonitorApi::trace_reply(const Query& q) const {
  const auto [dir, shot] = folder_and_shot(folders_.current(), q);
  const long frame = number_param(q, "frame", 0, 99'999'999);
  if (tracer_.empty()) throw BadRequest(501, "this monitor was started without the pixel inspector");
  const auto journal_ptr = journal_of(journals_, dir, shot);
  const farm::JournalContents& journal = *journal_ptr;
  const auto line = journal.frames.find(static_cast<int>(frame));
  if (line == journal.frames.end()) throw BadRequest(404, fmt::format("frame {} of '{}' is not finished", frame, shot));
  const farm::FrameSettings& st = line->second.settings;
  if (st.window.windowed())
    throw BadRequest(409, fmt::format("frame {} is a --region of its frame: trace the whole frame's pixel with "
                                      "`lightcone trace` instead",
                                      frame));
  const long x = number_param(q, "x", 0, st.width - 1), y = number_param(q, "y", 0, st.height - 1);
  const auto events = events_of(events_, dir, shot);
  const farm::EventSummary& ev = *events;
  if (!ev.run || ev.run->script.empty())
    throw BadRequest(409, "the render's event log does not name its shot script (rendered by an older lightcone?)");
  std::error_code ec;
  if (!fs::is_regular_file(ev.run->script, ec))
    throw BadRequest(409, fmt::format("the shot script {} is gone", ev.run->script));
  PixelRequest r;
  r.script = ev.run->script;
  r.frame = static_cast<int>(frame);
  r.x = static_cast<int>(x);
  r.y = static_cast<int>(y);
  r.width = st.width;
  r.height = st.height;
  r.delivery = st.delivery;
  // The same pixel of the same frame as rendered (its inputs and when it
  // was stored), traced before: its answer again.
  const std::string key = fmt::format("{}/{}/{}/{}/{}/{}/{}/{}", number_param(q, "folder", 0, 1L << 30), shot, frame, x, y,
                                      line->second.inputs, line->second.cost.finished, r.script.string());
  if (auto cached = traces_.find(key)) return {200, "application/json", std::move(*cached)};
  // One trace at a time: each is a process working a CPU the render may
  // want, and a page clicked about would start one per click.
  std::unique_lock busy(traces_.busy, std::try_to_lock);
  if (!busy.owns_lock())
    throw BadRequest(429, "the pixel inspector is tracing another pixel (one at a time): try again in a moment");
  try {
    std::string body = trace_pixel_json(tracer_, r);
    traces_.keep(key, body);
    return {200, "application/json", std::move(body)};
  } catch (const std::runtime_error& e) {
    throw BadRequest(422, e.what());
  }
}

Reply MonitorApi::layer_png(const Query& q) const {
  const auto [dir, shot] = folder_and_shot(folders_.current(), q);
  const long frame = number_param(q, "frame", 0, 99'999'999);
  const auto wanted = q.find("layer");
  if (wanted == q.end()) throw BadRequest(400, "missing parameter 'layer'");
  // Read through the file opened here (regular, not a link, never a FIFO
  // swapped in after the check: that would hold a server thread for good),
  // and no larger than what the monitor serves.
  const FolderFile exr(frame_file(dir, farm::frame_path(dir, shot, static_cast<int>(frame), "exr"), frame, shot));
  if (exr.missing()) throw BadRequest(404, fmt::format("frame {} of '{}' has no EXR", frame, shot));
  if (exr.refused()) throw BadRequest(403, fmt::format("frame {}'s EXR {}", frame, exr.why()));
  if (exr.size() > max_served_bytes)
    throw BadRequest(413, fmt::format("frame {}'s EXR is larger than {} bytes: not read", frame, max_served_bytes));
  const FrameImage image = read_exr(exr.open_file_path());
  FrameImage picture;
  if (!layer_picture(image, wanted->second, picture)) {
    std::string names;
    for (const auto& l : image.layers) names += (names.empty() ? "" : ", ") + l.name;
    throw BadRequest(404, names.empty() ? fmt::format("frame {} has no data layers (render with --layers)", frame)
                                        : fmt::format("frame {} has no layer '{}'; it has {}", frame,
                                                      wanted->second.substr(0, 100), names));
  }
  // Through a temporary file: the PNG writer writes by path.  It writes
  // through the descriptor mkstemp made (durable_file.hpp's
  // descriptor_path), never by the name in the shared temporary directory;
  // read_file reads the name back only as a regular file, not a link.
  std::string pattern = (fs::temp_directory_path() / "lightcone-layer-XXXXXX").string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) throw std::runtime_error("cannot make a temporary file for the layer's picture");
  struct Remove {
    std::string path;
    int fd;
    ~Remove() {
      ::close(fd);
      std::remove(path.c_str());
    }
  } remove{pattern, fd};
  write_png(descriptor_path(fd), picture);
  return {200, "image/png", read_file(pattern)};
}

}  // namespace lc::monitor
