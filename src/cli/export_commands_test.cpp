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

TEST(CliExport, SnapExportImportRoundTrip) {
  const std::string snapped = temp_path("fq16.json"), exported = temp_path("fq.vk.txt"),
                    back = temp_path("fq-back.json");
  CliRun r = run({"snap", "flipquad", "-o", snapped, "--objective", "laine-aila", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto js = nlohmann::json::parse(r.out);
  EXPECT_NEAR(js["e2_before"].get<double>(), 0.3643, 1e-4);  // Laine-Aila Table 2
  EXPECT_GT(js["e2_snapped"].get<double>(), js["e2_before"].get<double>());
  EXPECT_EQ(js["n"], 2.0);
  r = run({"export", snapped, "--api", "vulkan", "--grid", "2x2", "-o", exported});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(exported).find("sampleLocationGridSize = {2, 2}"), std::string::npos);
  r = run({"import", exported, "-o", back});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto a = nlohmann::json::parse(slurp(snapped)), b = nlohmann::json::parse(slurp(back));
  EXPECT_EQ(a["sets"], b["sets"]);
  EXPECT_EQ(a["kernels"], b["kernels"]);
  EXPECT_EQ(a["tile"], b["tile"]);
  // Off the lattice, a grid the API cannot hold, a malformed file: named errors, no output.
  r = run({"export", "flipquad", "--api", "d3d12-tier2", "-o", temp_path("x.txt")});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("is not on the 1/16 lattice; snap it first"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(temp_path("x.txt")));
  r = run({"export", "flipquad", "--snap", "--api", "metal"});
  EXPECT_NE(r.err.find("does not fit metal's pixel grid"), std::string::npos) << r.err;
  r = run({"export", "flipquad", "--snap", "--api", "d3d12-tier2", "--shader", "glsl"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("texelFetch"), std::string::npos);
  std::ofstream(temp_path("bad.txt")) << "// aapat-export 1 profile=vulkan grid=1x1\n";
  r = run({"import", temp_path("bad.txt")});
  EXPECT_NE(r.err.find("needs profile=, grid=, samples= and footprint="), std::string::npos)
      << r.err;
}

TEST(CliExport, LatticeOptimizationAndOptimizedWeights) {
  CliRun r = run({"optimize", "--family", "P(1,1,4)", "--starts", "4", "--api", "d3d12-tier1",
                  "--objective", "laine-aila", "-o", temp_path("l.json")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("lattice 1/16 for d3d12-tier1"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1x1 pixel grid, 4x MSAA"), std::string::npos) << r.out;
  const auto saved = nlohmann::json::parse(slurp(temp_path("l.json")));
  for (const auto& s : saved["sets"][0]) {
    const double x = s[0].get<double>() * 16, y = s[1].get<double>() * 16;
    EXPECT_EQ(x, std::round(x));
    EXPECT_EQ(y, std::round(y));
  }
  r = run({"optimize", "--family", "P(4,1+,2)", "--placement", "left,right,bottom,top", "--api",
           "d3d12-tier1", "--starts", "2"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("does not fit d3d12-tier1's pixel grid"), std::string::npos) << r.err;
  r = run({"eval", "msaa-8", "--optimized-weights", "--objective", "laine-aila", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  EXPECT_NEAR(rows[0]["e2"].get<double>(), 0.3437, 1e-4);
  EXPECT_LT(rows[0]["e2_optimized_weights"].get<double>(), 0.3437 - 0.02);
}

}  // namespace
}  // namespace aapat
