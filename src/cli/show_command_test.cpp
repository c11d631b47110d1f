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

TEST(CliShow, ShowWritesDrawingAndPatternFile) {
  const std::string svg = temp_path("fq.svg"), json = temp_path("fq.json");
  const CliRun r = run({"show", "flipquad", "-o", svg});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("P(4,1+,2)"), std::string::npos);
  EXPECT_NE(r.out.find("left"), std::string::npos);
  EXPECT_TRUE(fs::exists(svg));
  ASSERT_EQ(run({"show", "flipquad", "-o", json}).code, 0);
  const CliRun again = run({"eval", json, "--objective", "laine-aila", "--json"});
  ASSERT_EQ(again.code, 0) << again.err;
  EXPECT_NEAR(nlohmann::json::parse(again.out)["rows"][0]["e2"].get<double>(), 0.364, 0.001);
}

}  // namespace
}  // namespace aapat
