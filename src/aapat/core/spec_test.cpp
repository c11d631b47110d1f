#include "aapat/core/spec.h"

#include <gtest/gtest.h>

#include "testing/error_message.h"

namespace aapat {
namespace {

const SpecInfo kInfo{"ring",
                     "a test entry",
                     "nowhere",
                     {{"radius", "1/2", "the radius"}, {"count", "", "how many (required)"}}};

TEST(Spec, ParsesValuesFractionsAndDefaults) {
  const Spec s("shape", kInfo, "count=3");
  EXPECT_EQ(s.name(), "ring");
  EXPECT_EQ(s.number("radius"), 0.5);
  EXPECT_FALSE(s.given("colour"));
  EXPECT_TRUE(s.given("count"));
  EXPECT_EQ(s.whole("count", 1, 10), 3);
  EXPECT_EQ(s.canonical(), "ring:radius=1/2,count=3");
  EXPECT_EQ(Spec("shape", kInfo, "radius=-1/4,count=2").number("radius"), -0.25);
  EXPECT_EQ(kInfo.usage(), "ring:radius=1/2,count=COUNT");
}

TEST(Spec, RefusesWhatItDoesNotTake) {
  const auto message = [](const char* params, const char* key = "count") {
    return testing::error_message([&] { Spec("shape", kInfo, params).number(key); });
  };
  EXPECT_NE(message("q=1").find("shape ring: unknown parameter 'q=1' (it takes radius, count)"),
            std::string::npos);
  EXPECT_NE(message("count=nan").find("not a finite number"), std::string::npos);
  EXPECT_NE(message("radius=1").find("count"), std::string::npos);  // required, not given
  EXPECT_NE(testing::error_message([] {
              Spec("shape", kInfo, "count=2.5").whole("count", 1, 9);
            }).find("count"),
            std::string::npos);
  EXPECT_NE(testing::error_message([] {
              Spec("shape", kInfo, "count=99").whole("count", 1, 9);
            }).find("count"),
            std::string::npos);
}

TEST(Spec, SplitsNameAndParameters) {
  EXPECT_EQ(split_spec(" gaussian:sigma=0.5 ").first, "gaussian");
  EXPECT_EQ(split_spec("gaussian:sigma=0.5").second, "sigma=0.5");
  EXPECT_EQ(split_spec("box").second, "");
}

TEST(Registry, UnknownNamesSuggestTheNearest) {
  const Registry<int> r("shape", {{kInfo, [](const Spec& s) { return s.whole("count", 1, 9); }}});
  EXPECT_EQ(r.make("ring:count=4"), 4);
  EXPECT_TRUE(r.contains("ring:count=1"));
  EXPECT_EQ(r.names(), "ring");
  EXPECT_NE(testing::error_message([&] {
              r.make("rign");
            }).find("unknown shape 'rign' (did you mean 'ring'?): known shapes are ring"),
            std::string::npos);
}

}  // namespace
}  // namespace aapat
