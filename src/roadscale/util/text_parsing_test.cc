#include "roadscale/util/text_parsing.h"

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(TextParsing, TrimRemovesSpacesTabsAndLineEndsAroundTheText) {
  EXPECT_EQ(Trim("  P0:\t\r\n"), "P0:");
  EXPECT_EQ(Trim("a b"), "a b");
  EXPECT_EQ(Trim(" \t\r\n"), "");
  EXPECT_EQ(Trim(""), "");
}

TEST(TextParsing, ParsesNumbersWithExponentsAndTabs) {
  const auto numbers = ParseNumbers("1.5\t-2e-3  7 ", "f.txt", 3);
  ASSERT_EQ(numbers.size(), 3u);
  EXPECT_DOUBLE_EQ(numbers[0], 1.5);
  EXPECT_DOUBLE_EQ(numbers[1], -2e-3);
  EXPECT_DOUBLE_EQ(numbers[2], 7.0);
}

TEST(TextParsing, RejectsGarbageNamingFileAndLine) {
  try {
    ParseNumbers("1.0 abc", "poses.txt", 12);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "poses.txt:12: expected a number, found 'abc'");
  }
  EXPECT_THROW(ParseNumbers("nan", "f", 1), Error);
  EXPECT_THROW(ParseNumbers("1e999", "f", 1), Error);
  EXPECT_THROW(ParseNumbers("2.5x", "f", 1), Error);
}

TEST(TextParsing, BlankAndCommentLines) {
  EXPECT_TRUE(IsBlankOrComment(""));
  EXPECT_TRUE(IsBlankOrComment("  \t\r"));
  EXPECT_TRUE(IsBlankOrComment("  # a comment"));
  EXPECT_FALSE(IsBlankOrComment(" 1 2 # trailing"));
}

TEST(TextParsing, ForEachLineNumbersLinesAndSkipsAByteOrderMark) {
  std::vector<std::string> lines;
  std::vector<int> numbers;
  const auto collect = [&](std::string_view line, int number) {
    lines.emplace_back(line);
    numbers.push_back(number);
  };
  ForEachLine("\xEF\xBB\xBFP0: 1\n\nlast", collect);
  EXPECT_EQ(lines, (std::vector<std::string>{"P0: 1", "", "last"}));
  EXPECT_EQ(numbers, (std::vector<int>{1, 2, 3}));
  lines.clear();
  ForEachLine("a\r\nb\n", collect);
  EXPECT_EQ(lines, (std::vector<std::string>{"a\r", "b"}));
  lines.clear();
  ForEachLine("", collect);
  EXPECT_TRUE(lines.empty());
}

}  // namespace
}  // namespace roadscale
