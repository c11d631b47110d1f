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

TEST(CliGenerate, GenerateWritesCsvAndPatternFiles) {
  CliRun r = run({"generate", "n-rooks", "--n", "6", "--seed", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 7);  // header + 6 points
  const std::string json = temp_path("rooks.json"), csv = temp_path("rooks.csv");
  ASSERT_EQ(run({"generate", "n-rooks", "--n", "6", "--seed", "2", "-o", json}).code, 0);
  ASSERT_EQ(run({"generate", "n-rooks", "--n", "6", "--seed", "2", "-o", csv}).code, 0);
  const CliRun e = run({"eval", json, "--json"});
  ASSERT_EQ(e.code, 0) << e.err;
  EXPECT_EQ(nlohmann::json::parse(e.out)["rows"][0]["family"], "P(1,1,6)");
  // The CSV and the pattern file hold the same points.
  const CliRun a = run({"discrepancy", csv, "--json"}), b = run({"discrepancy", json, "--json"});
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_NEAR(nlohmann::json::parse(a.out)["l2_star"].get<double>(),
              nlohmann::json::parse(b.out)["l2_star"].get<double>(), 1e-12);
}

}  // namespace
}  // namespace aapat
