#pragma once
// Reading a text file line by line in bounded memory: a line longer than
// the reader's limit is not held whole (a 2 GB file of one line must not
// cost 2 GB before it is refused), only its first `max_length` bytes and
// its true length.  Used by every reader of line-based files (the star
// catalogue, the render journal), which each decide what an overlong line
// means for them.

#include <cstddef>
#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <string_view>

namespace lc {

struct TextLine {
  std::string_view text;     // the line without its '\n', cut at the reader's limit when too_long
  long number = 0;           // 1-based
  std::uintmax_t bytes = 0;  // bytes the line took in the stream, its '\n' included when it has one
  bool too_long = false;     // longer than the limit: `text` holds only its first max_length bytes
  bool complete = false;     // ended with '\n' (false: the stream's last line, cut short)
};

class LineReader {
 public:
  // Input: a stream opened for reading (binary mode: the bytes counted are
  // the file's) and the longest line held whole.  The stream must outlive
  // the reader.
  LineReader(std::istream& in, std::size_t max_length);

  // The next line, or nullopt at the end of the stream.  The view is valid
  // until the next call.  Memory stays at max_length bytes whatever the
  // lines' lengths; an overlong line's rest is skipped, not stored.
  std::optional<TextLine> next();

  // Whether reading stopped on an I/O error rather than the end of the file.
  bool failed() const { return in_.bad(); }

  std::size_t max_length() const { return max_length_; }

 private:
  std::istream& in_;
  std::size_t max_length_;
  std::string buffer_;
  long number_ = 0;
};

}  // namespace lc
