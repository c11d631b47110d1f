#include "aapat/study/optimize_run.h"

#include <gtest/gtest.h>

#include <cmath>

#include "aapat/core/objective.h"
#include "aapat/optimize/problem.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// Under the papers' objective and closed pixel the search reaches Laine-Aila
// Table 2's best P(1,1,4), 0.3587; kept strictly inside (the default) it
// stays 1/64 pixel off every border, a little above.
TEST(OptimizeRun, ReachesThePublishedOptimumAndKeepsSamplesInsideByDefault) {
  OptimizeRunSettings s;
  s.family = "P(1,1,4)";
  s.starts = 16;
  s.strictly_inside = false;
  const Objective papers = named_objective(kPapersObjective);
  const OptimizeRunResult closed = optimize_run(papers, s);
  EXPECT_NEAR(closed.best_start().run.final_e2, 0.3587, 1e-4);  // Laine-Aila Table 2
  s.strictly_inside = true;
  const OptimizeRunResult inside = optimize_run(papers, s);
  EXPECT_GE(inside.best_start().run.final_e2, closed.best_start().run.final_e2 - 1e-12);
  for (const Vec2& v : inside.best.sets[0]) {
    EXPECT_LE(std::abs(v.x), 0.5 - kInsideMargin + 1e-15);
    EXPECT_LE(std::abs(v.y), 0.5 - kInsideMargin + 1e-15);
  }
  EXPECT_EQ(inside.best.name, "P(1,1,4)-laine-aila-seed1");
  EXPECT_EQ(inside.objective, papers);
}

// The JSON is the one --json prints: the objective's four keys and the result.
TEST(OptimizeRun, JsonNamesItsObjective) {
  OptimizeRunSettings s;
  s.family = "P(1,1,2)";
  s.starts = 2;
  const OptimizeRunResult r = optimize_run(named_objective(kRecommendedObjective), s);
  const JsonObject doc = optimize_run_json(r);
  EXPECT_EQ(doc["command"], "optimize");
  EXPECT_EQ(doc["objective"], "recommended");
  EXPECT_EQ(doc["norm"], "2");
  EXPECT_EQ(doc["e2"].get<double>(), r.best_start().run.final_e2);
  EXPECT_EQ(doc["pattern"]["provenance"]["objective"], "recommended");
}

TEST(OptimizeRun, RefusesSettingsThatCannotRun) {
  OptimizeRunSettings s;
  const Objective o = named_objective(kRecommendedObjective);
  EXPECT_NE(testing::error_message([&] { optimize_run(o, s); }).find("give either a family"),
            std::string::npos);
  s.family = "P(1,1,2)";
  s.starts = 0;
  EXPECT_NE(testing::error_message([&] { optimize_run(o, s); }).find("starts 0"),
            std::string::npos);
  s.starts = 1;
  s.api = "vulkan";
  s.lattice = 8;
  EXPECT_NE(testing::error_message([&] { optimize_run(o, s); }).find("1/16 pixel lattice"),
            std::string::npos);
}

}  // namespace
}  // namespace aapat
