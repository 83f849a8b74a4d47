#include "store/event_file.hpp"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include <ext/stdio_filebuf.h>

#include <fcntl.h>

#include <fmt/format.h>

#include "core/line_reader.hpp"
#include "store/checked_line.hpp"
#include "store/durable_file.hpp"

namespace lc::farm {

namespace fs = std::filesystem;

namespace {

// "key=value key=value": nullopt when a token is not key=value.
std::optional<Event> parse_event(const std::string& content) {
  Event e;
  std::size_t pos = 0;
  while (pos < content.size()) {
    const std::size_t end = std::min(content.find(' ', pos), content.size());
    const std::string token = content.substr(pos, end - pos);
    pos = end + 1;
    if (token.empty()) continue;
    const auto eq = token.find('=');
    if (eq == std::string::npos || eq == 0) return std::nullopt;
    e.fields[token.substr(0, eq)] = percent_decode(token.substr(eq + 1));
  }
  const auto t = e.fields.find("t"), kind = e.fields.find("event");
  if (t == e.fields.end() || kind == e.fields.end()) return std::nullopt;
  char* stop = nullptr;
  e.time = std::strtod(t->second.c_str(), &stop);
  if (stop != t->second.c_str() + t->second.size()) return std::nullopt;
  e.kind = kind->second;
  e.fields.erase(t);
  e.fields.erase("event");
  return e;
}

// The field `key` of e as a number (0 when absent or not one).
long field_long(const Event& e, const char* key) {
  const auto it = e.fields.find(key);
  return it == e.fields.end() ? 0 : std::strtol(it->second.c_str(), nullptr, 10);
}

// Whether text is exactly an int (into value).
bool parse_int(const std::string& text, int& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

fs::path events_file(const fs::path& dir, const std::string& shot) { return dir / (shot + ".events"); }

std::string format_holdings(const std::vector<RankHolding>& holdings, std::size_t max_chars, bool* complete) {
  std::string out;
  if (complete) *complete = true;
  for (const RankHolding& h : holdings) {
    if (h.sets == 0) continue;
    const std::string entry = fmt::format("{}{}:{}:{}", out.empty() ? "" : ",", h.rank, h.sets, fmt::join(h.frames, "+"));
    if (out.size() + entry.size() > max_chars) {
      if (complete) *complete = false;
      break;
    }
    out += entry;
  }
  return out;
}

std::vector<RankHolding> parse_holdings(const std::string& text) {
  std::vector<RankHolding> out;
  std::istringstream entries(text);
  for (std::string entry; std::getline(entries, entry, ',');) {
    const auto a = entry.find(':'), b = entry.find(':', a == std::string::npos ? a : a + 1);
    if (a == std::string::npos || b == std::string::npos) continue;
    RankHolding h;
    if (!parse_int(entry.substr(0, a), h.rank) || !parse_int(entry.substr(a + 1, b - a - 1), h.sets)) continue;
    std::istringstream frames(entry.substr(b + 1));
    bool ok = true;
    for (std::string f; ok && std::getline(frames, f, '+');) {
      int frame = 0;
      ok = parse_int(f, frame);
      h.frames.push_back(frame);
    }
    if (ok) out.push_back(std::move(h));
  }
  return out;
}

EventSummary read_events(const fs::path& file, std::size_t keep) {
  EventSummary s;
  // A log that is no regular file of lightcone's (a FIFO would block the
  // reader for good) reads as none, as a missing one does.
  OwnFile own;
  try {
    own = open_own_file(file, O_RDONLY, "read the event log");
  } catch (const std::runtime_error&) {
    return s;
  }
  if (own.fd < 0) return s;
  __gnu_cxx::stdio_filebuf<char> buffer(own.fd, std::ios::in | std::ios::binary);  // closes the descriptor
  std::istream in(&buffer);
  return read_events(in, keep);
}

EventSummary read_events(std::istream& in, std::size_t keep) {
  // Input: the log's lines from its start, or from any line's start (the
  // monitor reads what was appended since it last read: its first line is
  // then an event, read as one).
  EventSummary s;
  LineReader lines(in, max_event_line);
  bool first = true;
  while (const auto line = lines.next()) {
    if (!line->complete || line->too_long) {
      if (line->complete) ++s.bad_lines;
      continue;
    }
    const auto content = checked_content(std::string(line->text));
    if (first) {
      first = false;
      if (content && *content == events_header) continue;
    }
    const auto e = content ? parse_event(*content) : std::nullopt;
    if (!e) {
      ++s.bad_lines;
      continue;
    }
    if (e->kind == "run") {
      const int bad = s.bad_lines;
      s = EventSummary{};
      s.bad_lines = bad;
      RunStart r;
      r.time = e->time;
      r.pid = field_long(*e, "pid");
      r.host = e->fields.count("host") ? e->fields.at("host") : "";
      r.ranks = static_cast<int>(field_long(*e, "ranks"));
      r.threads = static_cast<int>(field_long(*e, "threads"));
      r.todo = static_cast<int>(field_long(*e, "todo"));
      r.done_before = static_cast<int>(field_long(*e, "done"));
      const std::string size = e->fields.count("size") ? e->fields.at("size") : "";
      std::sscanf(size.c_str(), "%dx%d", &r.width, &r.height);
      r.script = e->fields.count("script") ? e->fields.at("script") : "";
      r.cwd = e->fields.count("cwd") ? e->fields.at("cwd") : "";
      if (e->fields.count("command")) {
        std::istringstream args(e->fields.at("command"));
        for (std::string arg; std::getline(args, arg, '\0');) r.command.push_back(std::move(arg));
      }
      s.run = r;
    } else if (e->kind == "rank") {
      if (s.ranks.size() < max_summary_ranks) s.ranks.push_back(*e);
    } else if (e->kind == "lost") {
      if (s.lost.size() < max_summary_ranks) s.lost.push_back(static_cast<int>(field_long(*e, "rank")));
    } else if (e->kind == "progress") {
      s.progress = *e;
    } else if (e->kind == "frame") {
      ++s.frames_stored;
    } else if (e->kind == "error") {
      if (s.errors.size() < keep) s.errors.push_back(*e);
    } else if (e->kind == "end") {
      s.end = *e;
    }
    s.recent.push_back(*e);
    if (s.recent.size() > keep) s.recent.pop_front();
  }
  return s;
}

}  // namespace lc::farm
