#include "aapat/core/json_depth.h"

#include <gtest/gtest.h>

#include <string>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

// Arrays and objects count; brackets in strings, escaped quotes included, do not.
TEST(JsonDepth, CountsArraysAndObjectsButNotStrings) {
  EXPECT_EQ(json_depth("1"), 0);
  EXPECT_EQ(json_depth("{\"a\": [1, [2, {\"b\": 3}]]}"), 4);
  EXPECT_EQ(json_depth("[\"[[[[\", \"\\\"]]]\\\"[[\"]"), 1);
  EXPECT_EQ(json_depth("{\"name\": \"a \\\\\", \"x\": [[]]}"), 3);  // an escaped backslash ends
  EXPECT_EQ(json_depth("]]]][["), 2);  // malformed: counted as far as it goes
}

// 100,000 arrays deep is refused by name and depth, without recursion; the
// limit itself is accepted.
TEST(JsonDepth, RefusesPastTheLimitWithoutRecursing) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  EXPECT_EQ(json_depth(deep), 100000);
  try {
    check_json_depth(deep, "pattern file p.json");
    FAIL() << "not refused";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pattern file p.json: nested 100000 deep"),
              std::string::npos);
  }
  const std::string at_limit = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  EXPECT_NO_THROW(check_json_depth(at_limit, "x"));
}

}  // namespace
}  // namespace aapat
