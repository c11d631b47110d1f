#include "aapat/core/objective.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/nearest_name.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

TEST(Objective, TheNamedObjectivesAreTheStudysAndThePapers) {
  const Objective& rec = named_objective("recommended");
  EXPECT_EQ(rec.filter, "mitchell:b=1/3,c=1/3");
  EXPECT_EQ(rec.acuity, "uniform:step=1,weight=1");
  EXPECT_EQ(rec.norm, 2);
  const Objective& papers = named_objective("laine-aila");
  EXPECT_EQ(papers.acuity, "laine-aila");
  EXPECT_EQ(papers.norm, Metric::kMaxNorm);
  EXPECT_EQ(parse_objective(kDefaultObjective), rec);
  EXPECT_EQ(rec.text(), "recommended");
  EXPECT_EQ(objective_infos().size(), objective_registry().size());
}

// The text form round-trips, and overrides that spell out a named objective
// give it its name back.
TEST(Objective, TextRoundTripsAndOverridesKeepTheName) {
  const Objective custom = parse_objective("laine-aila norm=2 filter=lanczos:lobes=2");
  EXPECT_EQ(custom.name(), "");
  EXPECT_EQ(custom.filter, "lanczos:lobes=2");
  EXPECT_EQ(parse_objective(custom.text()), custom);
  EXPECT_EQ(parse_objective("filter=mitchell acuity=laine-aila norm=inf").name(), "laine-aila");
  EXPECT_EQ(parse_objective("laine-aila acuity=uniform:step=1 norm=2").name(), "recommended");
  EXPECT_EQ(override_objective(named_objective("recommended"), std::nullopt, "laine-aila",
                               Metric::kMaxNorm)
                .text(),
            "laine-aila");
}

// The objective's metric is the metric of its parts: Laine-Aila Table 2's
// FLIPQUAD under the papers' objective.
TEST(Objective, ItsMetricIsThePapersUnderLaineAila) {
  const Metric m = named_objective("laine-aila").metric();
  EXPECT_EQ(m.angle_count(), 4);
  EXPECT_EQ(objective_of(m), named_objective("laine-aila"));
  EXPECT_EQ(named_objective("recommended").metric().angle_count(), 180);
}

TEST(Objective, BadTextIsNamedWithTheNearestName) {
  const auto message = [](const char* text) {
    return testing::error_message([&] { parse_objective(text, "--objective"); });
  };
  EXPECT_NE(message("recomended").find("did you mean 'recommended'"), std::string::npos);
  EXPECT_NE(message("laine-aila acuty=x").find("unknown key 'acuty' (did you mean 'acuity'?)"),
            std::string::npos);
  EXPECT_NE(message("laine-aila norm=2 norm=3").find("'norm' is given twice"), std::string::npos);
  EXPECT_NE(message("").find("empty"), std::string::npos);
  EXPECT_NE(message("norm=0.5").find("not a valid p"), std::string::npos);
  EXPECT_NE(message("filter=nosuch").find("unknown filter 'nosuch'"), std::string::npos);
  EXPECT_NE(message("laine-aila norm").find("is not KEY=VALUE"), std::string::npos);
}

TEST(NearestName, SuggestsOnlyNearNames) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("EVAL", "eval"), 0u);
  EXPECT_EQ(edit_distance("rign", "ring"), 1u);  // a swap is one edit
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(nearest_name("evl", {"eval", "export", "list"}), "eval");
  EXPECT_EQ(nearest_name("aapat-taa8", {"aapat-taa-8", "aapat-taa-16"}), "aapat-taa-8");
  EXPECT_EQ(nearest_name("teapot", {"eval", "export", "list"}), std::nullopt);
  EXPECT_EQ(did_you_mean("zzzz", {"eval"}), "");
}

}  // namespace
}  // namespace aapat
