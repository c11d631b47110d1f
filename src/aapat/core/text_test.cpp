#include "aapat/core/text.h"

#include <gtest/gtest.h>

namespace aapat {
namespace {

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
