#include "monitor/parsed_cache.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

namespace lc::monitor {

namespace {

// How much of a file one step reads: the memory a parse holds beyond the
// contents.
constexpr std::size_t parse_chunk_bytes = 4u << 20;
// The bytes before where a parse stopped that are compared on the next
// read: they end in the last line's check, so a line written in their
// place differs in them.
constexpr std::size_t rewrite_check_bytes = 64;

}  // namespace

bool ParsedCacheBase::unchanged(const Mark& m, const FolderFile& file) {
  return m.device == file.device() && m.inode == file.inode() && m.size == file.size() &&
         m.modified_ns == file.modified_ns();
}

bool ParsedCacheBase::appended(const Mark& m, const FolderFile& file) {
  // The same size with a new time is a rewrite; a size below what was
  // parsed, a cut.
  if (m.device != file.device() || m.inode != file.inode() || m.size == file.size() || file.size() < m.parsed)
    return false;
  return m.before_parsed.empty() ||
         file.read_at(m.parsed - m.before_parsed.size(), m.before_parsed.size()) == m.before_parsed;
}

void ParsedCacheBase::mark_read(Mark& m, const FolderFile& file) {
  m.device = file.device();
  m.inode = file.inode();
  m.size = file.size();
  m.modified_ns = file.modified_ns();
  const std::size_t check = static_cast<std::size_t>(std::min<std::uintmax_t>(m.parsed, rewrite_check_bytes));
  m.before_parsed = file.read_at(m.parsed - check, check);
}

std::string ParsedCacheBase::chunk(const FolderFile& file, std::uintmax_t offset, bool* torn, std::uintmax_t* skip) {
  std::string text = file.read_at(offset, parse_chunk_bytes);
  const std::size_t cut = text.rfind('\n');
  if (cut != std::string::npos) {
    text.resize(cut + 1);
    return text;
  }
  std::uintmax_t end = offset + text.size();
  if (end >= file.size()) {  // the last line, cut short
    *torn = true;
    return {};
  }
  for (;;) {  // a line longer than a chunk: to its end
    const std::string more = file.read_at(end, parse_chunk_bytes);
    const std::size_t nl = more.find('\n');
    if (nl != std::string::npos) {
      *skip = end + nl + 1;
      return {};
    }
    end += more.size();
    if (more.empty() || end >= file.size()) {
      *torn = true;
      return {};
    }
  }
}

void JournalFormat::fold(Contents& into, const std::string& lines, std::uintmax_t offset, const std::string& name) {
  // Lines after the first parse as a journal of their own behind the
  // header, so that parse_journal's rules hold line for line.
  const std::string header = offset == 0 ? "" : farm::journal_header_line() + "\n";
  const farm::JournalContents part = farm::parse_journal(header + lines, name);
  for (const auto& [f, jf] : part.frames) into.frames[f] = jf;
  if (part.last_frame >= 0) into.last_frame = part.last_frame;
  for (const auto& [path, hash] : part.inputs) into.inputs[path] = hash;
  into.bad_lines += part.bad_lines;
  if (part.valid_bytes > header.size()) into.valid_bytes = offset + (part.valid_bytes - header.size());
}

void JournalFormat::overlong_line(Contents& into, std::uintmax_t offset, const std::string& name) {
  // As parse_journal: a bad line, but as the first, not a journal.
  if (offset == 0) throw std::runtime_error(fmt::format("{} is not a lightcone journal", name));
  ++into.bad_lines;
}

void EventFormat::fold(Contents& into, const std::string& lines, std::uintmax_t, const std::string&) {
  std::istringstream in(lines, std::ios::binary);
  farm::EventSummary part = farm::read_events(in, keep);
  // A run in the new lines starts the summary afresh, as read_events does;
  // else its events go on the run before.
  if (part.run) {
    part.bad_lines += into.bad_lines;
    into = std::move(part);
    return;
  }
  for (auto& r : part.ranks)
    if (into.ranks.size() < farm::max_summary_ranks) into.ranks.push_back(std::move(r));
  for (int r : part.lost)
    if (into.lost.size() < farm::max_summary_ranks) into.lost.push_back(r);
  if (part.progress) into.progress = std::move(part.progress);
  if (part.end) into.end = std::move(part.end);
  for (auto& e : part.errors)
    if (into.errors.size() < keep) into.errors.push_back(std::move(e));
  for (auto& e : part.recent) into.recent.push_back(std::move(e));
  while (into.recent.size() > keep) into.recent.pop_front();
  into.frames_stored += part.frames_stored;
  into.bad_lines += part.bad_lines;
}

void EventFormat::overlong_line(Contents& into, std::uintmax_t, const std::string&) { ++into.bad_lines; }

}  // namespace lc::monitor
