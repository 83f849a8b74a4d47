// The bounded line reader (engine/core/line_reader.hpp): lines and their
// byte counts as the stream holds them, a last line without its newline, a
// line of exactly the limit, and an overlong line held only to the limit
// while the lines after it still read.

#include "core/line_reader.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace lc {
namespace {

struct Seen {
  std::string text;
  long number;
  std::uintmax_t bytes;
  bool too_long, complete;
  bool operator==(const Seen&) const = default;
};

std::vector<Seen> read_all(const std::string& text, std::size_t max_length) {
  std::istringstream in(text, std::ios::binary);
  LineReader reader(in, max_length);
  std::vector<Seen> out;
  while (const auto l = reader.next()) out.push_back({std::string(l->text), l->number, l->bytes, l->too_long, l->complete});
  EXPECT_FALSE(reader.failed());
  return out;
}

TEST(LineReader, ReadsLinesWithTheirBytesAndALastLineWithoutNewline) {
  EXPECT_EQ(read_all("ab\n\ncde\nf", 8),
            (std::vector<Seen>{{"ab", 1, 3, false, true}, {"", 2, 1, false, true}, {"cde", 3, 4, false, true},
                               {"f", 4, 1, false, false}}));
  EXPECT_TRUE(read_all("", 8).empty());
  EXPECT_EQ(read_all("x\n", 8), (std::vector<Seen>{{"x", 1, 2, false, true}}));
}

TEST(LineReader, ALineOfExactlyTheLimitIsWhole) {
  EXPECT_EQ(read_all("abcd\nabcd", 4), (std::vector<Seen>{{"abcd", 1, 5, false, true}, {"abcd", 2, 4, false, false}}));
}

TEST(LineReader, AnOverlongLineIsCutAtTheLimitAndTheNextLinesStillRead) {
  const std::string junk(1'000'000, 'j');
  EXPECT_EQ(read_all("ok\n" + junk + "\nafter\n", 16),
            (std::vector<Seen>{{"ok", 1, 3, false, true},
                               {junk.substr(0, 16), 2, junk.size() + 1, true, true},
                               {"after", 3, 6, false, true}}));
  // Overlong and cut short: the stream's last line.
  EXPECT_EQ(read_all("ok\nabcdef", 4), (std::vector<Seen>{{"ok", 1, 3, false, true}, {"abcd", 2, 6, true, false}}));
}

}  // namespace
}  // namespace lc
