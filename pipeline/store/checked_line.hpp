#pragma once
// Lines that carry their own check: "<content> #<16 hex>", the hash of the
// content, so a reader can tell a whole line from one a crash cut short or
// a disk garbled (the journal, the event log); and how a field of such a
// line spells any text (percent escapes).

#include <optional>
#include <string>
#include <string_view>

#include "store/content_hash.hpp"

namespace lc::farm {

// `content` with " #<check>" appended.
inline std::string with_check(const std::string& content) { return content + " #" + to_hex(hash_bytes(content)); }

// The content of a complete line if its check matches, else nullopt.
inline std::optional<std::string> checked_content(const std::string& line) {
  const auto at = line.rfind(" #");
  if (at == std::string::npos) return std::nullopt;
  std::string content = line.substr(0, at);
  if (line.substr(at + 2) != to_hex(hash_bytes(content))) return std::nullopt;
  return content;
}

// Text as the value of a line's field: bytes other than letters, digits and
// "-._~/:,+" (less those in `also`, for a list's separator) as %XX; and
// back (a malformed escape is kept as it is).
std::string percent_encode(const std::string& text, std::string_view also = {});
std::string percent_decode(const std::string& text);

}  // namespace lc::farm
