#include "cli/animation_options.h"
#include "cli/app.h"
#include "testing/cli_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace aapat {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;
using testing::run;
using testing::slurp;
using testing::temp_path;

// Hasselgren Table 2: the best configuration of each cost reaches the
// published E2 of schemes A, C, E and F (to the paper's rounding), with the
// same structure: a corner and two edges off it (A), two corners and two
// edges (C), a corner and three edges (E), one sample on each edge (F).
TEST(CliEnumerate, BestPerCostReachesThePublishedSchemes) {
  const CliRun r =
      run({"enumerate", "--optimize", "--starts", "8", "--objective", "laine-aila", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  ASSERT_EQ(rows.size(), 85u);
  const std::map<double, std::pair<double, std::string>> expected = {
      {1.25, {0.554, "top-left,bottom,right"}},
      {1.5, {0.527, "top-right,top-left,bottom,left"}},
      {1.75, {0.488, "top-left,bottom,right,left"}},
      {2.0, {0.359, "bottom,right,top,left"}}};
  std::map<double, nlohmann::json> best;
  for (const auto& row : rows)  // ranked: the first row of each n is its best
    if (!best.count(row["n"].get<double>())) best[row["n"].get<double>()] = row;
  for (const auto& [n, e] : expected) {
    EXPECT_LT(best[n]["e2"].get<double>(), e.first + 0.0005) << n;
    EXPECT_EQ(best[n]["placement"], e.second) << n;
  }
}

TEST(CliEnumerate, CountsWithoutOptimizing) {
  CliRun r = run({"enumerate", "--cost", "1,1.25,1.5,1.75,2"});
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("total       94"), std::string::npos) << r.out;
  r = run({"enumerate", "--cost", "1.3"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--cost: 1.3 is not a multiple of 1/4"), std::string::npos) << r.err;
  r = run({"enumerate", "--gallery", temp_path("g.svg")});
  EXPECT_EQ(r.code, 1);
}

}  // namespace
}  // namespace aapat
