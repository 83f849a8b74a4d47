// Checked lines (store/checked_line.hpp): a whole line is told from one a
// crash cut short or a disk garbled, and any text survives a field.

#include <string>

#include <gtest/gtest.h>

#include "store/checked_line.hpp"

namespace lc::farm {
namespace {

TEST(CheckedLine, AWholeLineGivesBackItsContent) {
  const std::string line = with_check("frame=3 size=4x2");
  ASSERT_TRUE(checked_content(line));
  EXPECT_EQ(*checked_content(line), "frame=3 size=4x2");
}

TEST(CheckedLine, ACutOrChangedLineIsRefused) {
  const std::string line = with_check("frame=3 size=4x2");
  EXPECT_FALSE(checked_content(line.substr(0, line.size() - 1)));
  std::string changed = line;
  changed[6] = '4';
  EXPECT_FALSE(checked_content(changed));
  EXPECT_FALSE(checked_content("frame=3 size=4x2"));
}

TEST(CheckedLine, PercentEncodingRoundTrips) {
  const std::string text = "a b%c\n\t=#\xc3\xa9/:,+~";
  EXPECT_EQ(percent_encode(text).find_first_of(" \n\t=#"), std::string::npos);
  EXPECT_EQ(percent_decode(percent_encode(text)), text);
  EXPECT_EQ(percent_decode("100%"), "100%");
  EXPECT_EQ(percent_decode("%zz"), "%zz");
}

TEST(CheckedLine, PercentEncodingEscapesAListsSeparatorWhenAsked) {
  EXPECT_EQ(percent_encode("a,b"), "a,b");
  EXPECT_EQ(percent_encode("a,b", ","), "a%2Cb");
  EXPECT_EQ(percent_decode("a%2Cb"), "a,b");
}

}  // namespace
}  // namespace lc::farm
