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

TEST(CliDiscrepancy, DiscrepancyReportsAllThree) {
  const CliRun r = run({"discrepancy", "regular", "--n", "16", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_NEAR(d["star_upper"].get<double>(), 1 - std::pow(1 - 1.0 / 8, 2), 1e-12);  // closed form
  EXPECT_TRUE(d["star_is_exact"].get<bool>());
  EXPECT_EQ(d["star_exact"].get<double>(), d["star_upper"].get<double>());  // the value itself
  EXPECT_GT(d["edge"].get<double>(), 0.0);
  EXPECT_EQ(run({"discrepancy", "no-such"}).code, 1);
  const std::string bad = temp_path("bad.csv");
  std::ofstream(bad) << "0.5,0.5\n1.5,0.2\n";
  const CliRun e = run({"discrepancy", bad});
  EXPECT_EQ(e.code, 1);
  EXPECT_NE(e.err.find("line 2: (1.5, 0.2) lies outside the unit square"), std::string::npos)
      << e.err;
}

TEST(CliDiscrepancy, DiscrepancyComputesOnlyTheMeasuresAsked) {
  // 200,000 points: past the star and edge limit, within the L2-star one.
  const CliRun r =
      run({"discrepancy", "halton", "--n", "200000", "--measure", "l2-star", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_TRUE(d.contains("l2_star"));
  EXPECT_FALSE(d.contains("star_upper") || d.contains("edge"));
  const CliRun t = run({"discrepancy", "regular", "--n", "16", "--measure", "edge,star"});
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_EQ(t.out.find("L2-star"), std::string::npos);
  EXPECT_NE(t.out.find("edge discrepancy"), std::string::npos);
  const CliRun bad = run({"discrepancy", "regular", "--measure", "l3"});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(
      bad.err.find("--measure 'l3': the measures are l2-star, l2-generalized, l2-centred, "
                   "l2-wrap-around, l2-unanchored, l2-symmetric, l2-mixture, star, edge or all"),
      std::string::npos)
      << bad.err;
  // Every L2 kind, in the JSON and in the text, one line each.
  const CliRun all = run({"discrepancy", "halton", "--n", "256", "--measure", "all", "--json"});
  ASSERT_EQ(all.code, 0) << all.err;
  const auto j = nlohmann::json::parse(all.out);
  for (const char* key : {"l2_star", "l2_generalized", "l2_centred", "l2_wrap_around",
                          "l2_unanchored", "l2_symmetric", "star_upper", "edge"})
    EXPECT_TRUE(j.contains(key)) << key;
  const CliRun text = run({"discrepancy", "halton", "--n", "256", "--measure", "l2-wrap-around"});
  EXPECT_NE(text.out.find("  L2-wrap-around discrepancy  0."), std::string::npos) << text.out;
}

}  // namespace
}  // namespace aapat
