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

TEST(CliOptimize, WritesBestPatternWithProvenanceCsvAndSvg) {
  const std::string json = temp_path("best.json"), csv = temp_path("starts.csv"),
                    svg = temp_path("best.svg");
  const CliRun r = run({"optimize", "--family", "P(4,1+,2)", "--placement", "left,right,bottom,top",
                        "--starts", "8", "--seed", "3", "-o", json, "--csv", csv, "--svg", svg,
                        "--objective", "laine-aila"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(doc["family"], "P(4,1+,2)");
  const auto& prov = doc["provenance"];
  EXPECT_EQ(prov["seed"], "3");
  EXPECT_EQ(prov["filter"], "mitchell:b=1/3,c=1/3");
  EXPECT_EQ(prov["acuity"], "laine-aila");
  EXPECT_EQ(prov["objective"], "laine-aila");
  EXPECT_EQ(doc["name"], "P(4,1+,2)-laine-aila-seed3");  // named after its settings
  EXPECT_TRUE(prov.contains("start") && prov.contains("iterations"));
  EXPECT_LT(std::stod(prov["e2"].get<std::string>()), 0.3595);  // Laine-Aila Table 2
  const CliRun again = run({"eval", json, "--objective", "laine-aila", "--json"});
  EXPECT_NEAR(nlohmann::json::parse(again.out)["rows"][0]["e2"].get<double>(),
              std::stod(prov["e2"].get<std::string>()), 1e-6);
  std::istringstream lines(slurp(csv));
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "start,initial_e2,final_e2,iterations,seconds,objective");
  int rows = 0;
  for (std::string l; std::getline(lines, l);) ++rows;
  EXPECT_EQ(rows, 8);
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
}

TEST(CliOptimize, SameSeedSameFileAnyThreads) {
  const std::string a = temp_path("t1.json"), b = temp_path("t2.json");
  ASSERT_EQ(run({"optimize", "--family", "P(1,1,3)", "--starts", "6", "--seed", "9", "--threads",
                 "1", "-o", a})
                .code,
            0);
  ASSERT_EQ(run({"optimize", "--family", "P(1,1,3)", "--starts", "6", "--seed", "9", "--threads",
                 "2", "-o", b})
                .code,
            0);
  EXPECT_EQ(slurp(a), slurp(b));
}

TEST(CliOptimize, PolishesAPatternAndReportsTheCostOfNonNegativeWeights) {
  const CliRun r =
      run({"optimize", "quincunx", "--weights-only", "--nonnegative", "--objective", "laine-aila"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("non-negative weights: E2 0.4842"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("unconstrained from the same start"), std::string::npos);
}

TEST(CliOptimize, BadArgumentsAreExplained) {
  CliRun r = run({"optimize"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("give either a family (a search) or a pattern (to polish)"),
            std::string::npos);
  r = run({"optimize", "--family", "P(4,1+,2)", "--placement", "left,right"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("says n = 2 but the placement costs 1"), std::string::npos) << r.err;
  r = run({"optimize", "--family", "P(1,1,2)", "--seeds", "blue"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--seeds: 'blue' is not jittered, poisson, uniform"), std::string::npos);
  r = run({"optimize", "--family", "P(1,1,2)", "--starts", "0"});
  EXPECT_NE(r.code, 0);
  r = run({"optimize", "--family", "P(1,1,2)", "-o", temp_path("x.txt")});
  EXPECT_EQ(r.code, 1);
  EXPECT_FALSE(fs::exists(temp_path("x.txt")));
}

TEST(CliOptimize, LockedSamplesStayAndFileSeedsStartFromTheFile) {
  const std::string seed = temp_path("seed.json"), out = temp_path("locked.json");
  ASSERT_EQ(run({"show", "flipquad", "-o", seed}).code, 0);
  const CliRun r = run({"optimize", "--family", "P(4,1+,2)", "--seeds", seed, "--starts", "4",
                        "--lock", "0,2", "--objective", "laine-aila", "-o", out});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto before = nlohmann::json::parse(slurp(seed))["sets"][0];
  const auto after = nlohmann::json::parse(slurp(out))["sets"][0];
  EXPECT_EQ(after[0], before[0]);
  EXPECT_EQ(after[2], before[2]);
  EXPECT_NE(after[1], before[1]);  // free to move, and it does
  CliRun bad = run({"optimize", "rgss", "--lock", "7"});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("--lock: sample 7 does not exist: the base pixel has samples 0..3"),
            std::string::npos);
  bad = run({"optimize", "--family", "P(1,1,2)", "--seeds", seed});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("is P(4,1+,2), not the family P(1,1,2)"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace aapat
