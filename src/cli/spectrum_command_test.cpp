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

// --fast: the non-uniform FFT, its bound in the JSON, its radial profile the
// exact one's within that bound; an odd size is refused by name.
TEST(CliSpectrum, FastSpectrumMatchesTheExactOneWithinItsBound) {
  const CliRun fast =
      run({"spectrum", "jittered", "--n", "1024", "--size", "64", "--fast", "--json"});
  const CliRun exact = run({"spectrum", "jittered", "--n", "1024", "--size", "64", "--json"});
  ASSERT_EQ(fast.code, 0) << fast.err;
  ASSERT_EQ(exact.code, 0) << exact.err;
  const auto f = nlohmann::json::parse(fast.out), e = nlohmann::json::parse(exact.out);
  EXPECT_EQ(f["method"], "fast");
  EXPECT_EQ(e["method"], "exact");
  const double bound = f["error_bound"];
  EXPECT_GT(bound, 0);
  EXPECT_LT(bound, 1e-6);
  ASSERT_EQ(f["rows"].size(), e["rows"].size());
  for (size_t i = 1; i < f["rows"].size(); ++i)
    EXPECT_NEAR(double(f["rows"][i]["power"]), double(e["rows"][i]["power"]), bound) << i;
  const CliRun odd = run({"spectrum", "jittered", "--size", "63", "--fast"});
  EXPECT_EQ(odd.code, 1);
  EXPECT_NE(odd.err.find("--size 63: the fast spectrum takes an even size"), std::string::npos)
      << odd.err;
}

TEST(CliSpectrum, SpectrumWritesImageRadialProfileAndOneDimensionalPlot) {
  const std::string png = temp_path("s.png"), csv = temp_path("s.csv"), svg = temp_path("s1d.svg");
  CliRun r = run({"spectrum", "jittered", "--n", "64", "--size", "32", "--realizations", "2", "-o",
                  png, "--csv", csv});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string bytes = slurp(png);
  ASSERT_GT(bytes.size(), 8u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  std::istringstream lines(slurp(csv));
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "radius,power,anisotropy_db");
  r = run({"spectrum", "--1d", "poisson", "--n", "500", "--frequencies", "1000", "--svg", svg});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(slurp(svg).find("<svg"), std::string::npos);
  r = run({"spectrum", "jittered", "--n", "16", "-o", temp_path("s.jpg")});
  EXPECT_EQ(r.code, 1);
  EXPECT_FALSE(fs::exists(temp_path("s.jpg")));
}

TEST(CliSpectrum, TilesAndOneDimensionalComparison) {
  const std::string json = temp_path("tile.json"), csv = temp_path("f8.csv");
  CliRun r = run({"generate", "jittered", "--n", "4", "--tile", "2", "-o", json});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("P(4,1,4)"), std::string::npos) << r.out;
  EXPECT_EQ(run({"eval", json}).code, 0);
  r = run(
      {"spectrum", "--1d", "poisson,jittered", "--n", "300", "--frequencies", "64", "--csv", csv});
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(slurp(csv));
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "frequency,poisson,jittered");
  EXPECT_EQ(run({"generate", "jittered", "--n", "4", "--tile", "2"}).code, 1);
}

}  // namespace
}  // namespace aapat
