// The text helpers every message and table shares (materials/core/text.h).
#include "materials/core/text.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace glossy::test {

TEST(Text, JoinedPutsTheSeparatorBetweenEveryTwoItemsEvenEmptyOnes) {
  EXPECT_EQ(joined(std::vector<std::string>{"a", "b", "c"}, ", "), "a, b, c");
  EXPECT_EQ(joined(std::vector<std::string>{"", "b"}, ", "), ", b") << "an empty first item still takes its separator";
  EXPECT_EQ(joined(std::vector<std::string>{"a", "", "c"}, "; "), "a; ; c");
  EXPECT_EQ(joined(std::vector<std::string>{}, ", "), "");
  EXPECT_EQ(joined(std::vector<int>{1, 22}, "+", [](int v) { return std::to_string(v); }), "1+22");
}

TEST(Text, CsvFieldQuotesOnlyWhatNeedsIt) {
  EXPECT_EQ(csvField("plain"), "plain");
  EXPECT_EQ(csvField("a,b"), "\"a,b\"");
  EXPECT_EQ(csvField("say \"hi\""), "\"say \"\"hi\"\"\"");
}

}  // namespace glossy::test
