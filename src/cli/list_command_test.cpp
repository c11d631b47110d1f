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

TEST(CliList, ListNamesCatalogFiltersAndTables) {
  const CliRun r = run({"list"});
  ASSERT_EQ(r.code, 0);
  for (const char* s : {"hasselgren-f", "msaa-16", "grid-NxN", "mitchell:b=1/3,c=1/3",
                        "lanczos:lobes=3", "laine-aila", "uniform:step=STEP"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

}  // namespace
}  // namespace aapat
