#include "core/line_reader.hpp"

#include <limits>

namespace lc {

LineReader::LineReader(std::istream& in, std::size_t max_length)
    : in_(in), max_length_(max_length), buffer_(max_length + 1, '\0') {}

std::optional<TextLine> LineReader::next() {
  // istream::getline stores at most max_length bytes (the last byte of the
  // buffer is its terminator) and sets failbit when the line goes on; the
  // rest is then skipped with ignore(), which does not store it.
  if (!in_.good()) return std::nullopt;
  in_.getline(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
  std::uintmax_t taken = static_cast<std::uintmax_t>(in_.gcount());  // the '\n' included when extracted
  TextLine line;
  if (in_.fail() && !in_.bad() && !in_.eof()) {
    // The buffer filled before a '\n': an overlong line.
    std::size_t stored = max_length_;
    in_.clear();
    in_.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
    const auto skipped = static_cast<std::uintmax_t>(in_.gcount());
    taken += skipped;
    line.text = std::string_view(buffer_.data(), stored);
    line.too_long = true;
    // ignore() stops after the '\n' or at the end of the stream (eofbit).
    line.complete = !in_.eof();
  } else {
    if (taken == 0) return std::nullopt;  // the end of the stream (or an error before any byte)
    line.complete = !in_.eof();
    const std::size_t stored = static_cast<std::size_t>(taken) - (line.complete ? 1 : 0);
    line.text = std::string_view(buffer_.data(), stored);
  }
  // A stream that ended without a '\n' leaves failbit unset but eofbit set;
  // the next call then reports the end.
  line.bytes = taken;
  line.number = ++number_;
  return line;
}

}  // namespace lc
