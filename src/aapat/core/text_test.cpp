#include "aapat/core/text.h"

#include <gtest/gtest.h>

namespace aapat {
namespace {

// A prefix never ends in half a character: "é" is two bytes, "€" three.
TEST(Text, Utf8PrefixEndsOnACharacter) {
  EXPECT_EQ(utf8_prefix("abc", 10), "abc");
  EXPECT_EQ(utf8_prefix("ab\xc3\xa9", 3), "ab");  // "abé" cut inside the é
  EXPECT_EQ(utf8_prefix("ab\xc3\xa9", 4), "ab\xc3\xa9");
  EXPECT_EQ(utf8_prefix("\xe2\x82\xac\xe2\x82\xac", 5), "\xe2\x82\xac");  // "€€" to 5 bytes: one €
  EXPECT_EQ(utf8_prefix("\xe2\x82\xac", 0), "");
}

TEST(Text, SplitAndTrim) {
  EXPECT_EQ(split("a,b,,c"), (std::vector<std::string_view>{"a", "b", "", "c"}));
  EXPECT_TRUE(split("").empty());
  EXPECT_EQ(split("one"), (std::vector<std::string_view>{"one"}));
  EXPECT_EQ(split("x;y", ';').size(), 2u);
  EXPECT_EQ(trim("  left \t\r"), "left");
  EXPECT_EQ(trim(""), "");
}

}  // namespace
}  // namespace aapat
