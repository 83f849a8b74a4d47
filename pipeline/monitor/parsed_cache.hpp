#pragma once
// The journals and event logs the monitor has parsed, kept between requests
// (docs/monitor.md, "Long renders").  Both files are only ever appended to
// (store/journal.hpp, telemetry/event_log.hpp), and the page polls every few
// seconds: parsing a 100,000-frame journal whole on every poll cost about a
// second of CPU a request.  So each file's parse is kept with where it
// stopped (the end of its last complete line) and, on the next request,
// only what was appended since is parsed and folded in.  What a full parse
// gives is what this gives (tests/unit/parsed_cache_test.cpp); the file is
// parsed whole again whenever it may not be the one parsed before: another
// inode, shorter than what was parsed, the bytes before where the parse
// stopped changed, or the same size with a new modification time.

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "store/event_file.hpp"
#include "store/journal.hpp"
#include "monitor/folder_file.hpp"

namespace lc::monitor {

// How a journal's lines parse and fold (farm::parse_journal).
struct JournalFormat {
  using Contents = farm::JournalContents;
  // Inputs: complete lines at byte `offset` of the file (0: its start, the
  // header first).  Output: `into` as a parse of the file up to their end.
  static void fold(Contents& into, const std::string& lines, std::uintmax_t offset, const std::string& name);
  // A line longer than a chunk at `offset` (never one lightcone writes).
  static void overlong_line(Contents& into, std::uintmax_t offset, const std::string& name);
  static void set_torn(Contents& into, bool torn) { into.torn_tail = torn; }
};

// How an event log's lines parse and fold (farm::read_events, keeping the
// last 200 events: what the page shows).
struct EventFormat {
  using Contents = farm::EventSummary;
  static constexpr std::size_t keep = 200;
  static void fold(Contents& into, const std::string& lines, std::uintmax_t offset, const std::string& name);
  static void overlong_line(Contents& into, std::uintmax_t offset, const std::string& name);
  static void set_torn(Contents&, bool) {}
};

class ParsedCacheBase {
 protected:
  // Where a file's parse stands.
  struct Mark {
    std::uint64_t device = 0, inode = 0;
    std::uintmax_t size = 0;       // the file's size at the last read
    std::int64_t modified_ns = 0;  // and its modification time
    std::uintmax_t parsed = 0;     // the end of its last complete line parsed
    std::string before_parsed;     // the bytes just before `parsed`, to notice a rewrite
    std::uint64_t used = 0;        // when last read, to drop the least recently used
  };
  // Whether `file` is the file `m` parsed, unchanged (nothing to read).
  static bool unchanged(const Mark& m, const FolderFile& file);
  // Whether `file` is the file `m` parsed with lines appended: only the tail is read.
  static bool appended(const Mark& m, const FolderFile& file);
  // The complete lines of `file` from `m.parsed`, a chunk at a time: each
  // handed to `lines(text, offset)`, a line longer than a chunk to
  // `overlong(offset)`; m.parsed advances past each.  Output: whether a
  // line cut short is left at the end (for the next read).  Then marks
  // `m` as having read `file`.
  template <class Lines, class Overlong>
  static bool read_tail(Mark& m, const FolderFile& file, Lines lines, Overlong overlong, std::uintmax_t& parsed_bytes);
  static void mark_read(Mark& m, const FolderFile& file);
  // The chunk of `file` from `offset` cut after its last newline; "" with
  // `*torn` when there is none before the end, "" with `*skip` set to the
  // end of an overlong line when there is none in a chunk.
  static std::string chunk(const FolderFile& file, std::uintmax_t offset, bool* torn, std::uintmax_t* skip);
};

template <class Format>
class ParsedCache : ParsedCacheBase {
 public:
  using Contents = typename Format::Contents;
  // Inputs: `file`, opened as FolderFile (a regular file; for a journal,
  // one whose head the caller has checked), `key` naming it (its path).
  // Output: its contents as a full parse gives them, shared (never changed
  // once returned).  Throws std::runtime_error as the full parse does.
  // Safe to call from several threads at once.
  std::shared_ptr<const Contents> read(const FolderFile& file, const std::string& key);

  // The bytes the last read() parsed (for the tests: a poll of an
  // unchanged file parses none).
  std::uintmax_t last_parsed_bytes() const {
    const std::lock_guard lock(mutex_);
    return last_parsed_bytes_;
  }

 private:
  struct Entry {
    Mark mark;
    std::shared_ptr<Contents> contents;
  };
  mutable std::mutex mutex_;
  std::map<std::string, Entry> entries_;
  std::uint64_t clock_ = 0;
  std::uintmax_t last_parsed_bytes_ = 0;
};

using JournalCache = ParsedCache<JournalFormat>;
using EventCache = ParsedCache<EventFormat>;

// The files kept: one per shot the page shows; beyond it the least
// recently read is dropped (a parent folder of many renders).
inline constexpr std::size_t max_cached_files = 128;

template <class Lines, class Overlong>
bool ParsedCacheBase::read_tail(Mark& m, const FolderFile& file, Lines lines, Overlong overlong, std::uintmax_t& parsed_bytes) {
  bool torn = false;
  while (m.parsed < file.size() && !torn) {
    std::uintmax_t skip = 0;
    const std::string text = chunk(file, m.parsed, &torn, &skip);
    if (skip) {
      overlong(m.parsed);
      parsed_bytes += skip - m.parsed;
      m.parsed = skip;
    } else if (!text.empty()) {
      lines(text, m.parsed);
      parsed_bytes += text.size();
      m.parsed += text.size();
    }
  }
  mark_read(m, file);
  return torn;
}

template <class Format>
std::shared_ptr<const typename Format::Contents> ParsedCache<Format>::read(const FolderFile& file, const std::string& key) {
  // Holds the lock through the parse: two polls of one file parse its tail
  // once, and a parse never changes contents another request holds (those
  // are copied first).
  const std::lock_guard lock(mutex_);
  last_parsed_bytes_ = 0;
  Entry& e = entries_[key];
  e.mark.used = ++clock_;
  if (e.contents && unchanged(e.mark, file)) return e.contents;
  if (!e.contents || !appended(e.mark, file)) {
    e = Entry{};
    e.mark.used = clock_;
    e.contents = std::make_shared<Contents>();
  } else if (e.contents.use_count() > 1) {
    e.contents = std::make_shared<Contents>(*e.contents);  // another request reads the old one
  }
  Contents& c = *e.contents;
  try {
    const bool torn = read_tail(
        e.mark, file, [&](const std::string& text, std::uintmax_t at) { Format::fold(c, text, at, key); },
        [&](std::uintmax_t at) { Format::overlong_line(c, at, key); }, last_parsed_bytes_);
    Format::set_torn(c, torn);
  } catch (...) {
    entries_.erase(key);
    throw;
  }
  std::shared_ptr<const Contents> out = e.contents;
  if (entries_.size() > max_cached_files) {
    auto oldest = entries_.begin();
    for (auto it = entries_.begin(); it != entries_.end(); ++it)
      if (it->second.mark.used < oldest->second.mark.used) oldest = it;
    entries_.erase(oldest);
  }
  return out;
}

}  // namespace lc::monitor
