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

TEST(CliFigure10, WritesTableAndPlot) {
  const std::string csv = temp_path("f10.csv");
  const CliRun r = run({"figure10", "--starts", "2", "--csv", csv});
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(slurp(csv));
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "family,n,e2,placement,objective");
  int rows = 0;
  for (std::string l; std::getline(lines, l);) ++rows;
  EXPECT_EQ(rows, 23);  // 4 families x n = 2..6, and P(4,1+,n) at 1.25, 1.5, 1.75
}

}  // namespace
}  // namespace aapat
