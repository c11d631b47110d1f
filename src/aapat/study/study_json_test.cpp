#include "aapat/study/study_json.h"

#include <gtest/gtest.h>

#include <cmath>

namespace aapat {
namespace {

// One point at the centre: Warnock's closed form gives the L2-star
// discrepancy sqrt(1/9 - 2 (3/4)^2 / 4 + 1/4) = sqrt(23/288); the star
// discrepancy is 3/4 (the box [0, 1/2 + e)^2 holds the point and has area
// 1/4 + ...), exact for so small a set. The document has the keys of the
// measures computed, in the documented order, and no others.
TEST(StudyJson, DiscrepancyOfTheCentreHasItsClosedForms) {
  const DiscrepancyReport d = discrepancy_report({{0.5, 0.5}}, parse_measures("l2-star,star"));
  const JsonObject doc = discrepancy_json("centre", d);
  EXPECT_EQ(doc["command"], "discrepancy");
  EXPECT_EQ(doc["source"], "centre");
  EXPECT_EQ(doc["points"], 1);
  EXPECT_NEAR(doc["l2_star"].get<double>(), std::sqrt(23.0 / 288.0), 1e-12);
  EXPECT_TRUE(doc["star_is_exact"].get<bool>());
  EXPECT_EQ(doc["star_exact"].get<double>(), doc["star_upper"].get<double>());
  EXPECT_NEAR(doc["star_upper"].get<double>(), 0.75, 1e-12);
  EXPECT_FALSE(doc.contains("edge"));
  EXPECT_FALSE(discrepancy_json("", d).contains("source"));  // Python's array has no source
}

// The enumeration's document: a row per configuration with E2 null until
// optimized; cost 1.25 has 9 configurations (generate/enumerate_test.cpp).
TEST(StudyJson, EnumerationRowsAreTheConfigurations) {
  EnumerationSettings s;
  s.costs = {1.25};
  const Objective o = named_objective(kPapersObjective);
  const Enumeration e = enumerate_study(o.metric(), s);
  const JsonObject doc = enumeration_json(o, s, e);
  EXPECT_EQ(doc["objective"], "laine-aila");
  ASSERT_EQ(doc["rows"].size(), 9u);
  for (const JsonObject& row : doc["rows"]) {
    EXPECT_EQ(row["n"], 1.25);
    EXPECT_TRUE(row["e2"].is_null());
    EXPECT_GE(row["samples_read"].get<int>(), 2);
  }
}

// Figure 10's rows name their series, the curve a plot draws them on.
TEST(StudyJson, Figure10RowsNameTheirSeries) {
  Figure10 f;
  f.series = {"P(1,1,n)", "P(4,1+,n)"};
  f.points = {{"P(1,1,2)", "", 2, 0.5, 0}, {"P(4,1+,1.25)", "top-left,bottom,right", 1.25, 0.6, 1}};
  const JsonObject doc = figure10_json(named_objective(kPapersObjective), {}, f);
  EXPECT_EQ(doc["rows"][0]["series"], "P(1,1,n)");
  EXPECT_EQ(doc["rows"][1]["series"], "P(4,1+,n)");
  EXPECT_EQ(doc["rows"][1]["placement"], "top-left,bottom,right");
  EXPECT_EQ(doc["starts"], Figure10Settings{}.starts);
}

}  // namespace
}  // namespace aapat
