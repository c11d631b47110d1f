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

TEST(CliRender, ImageErrorImageAndHistogram) {
  const std::string png = temp_path("r.png"), err = temp_path("e.png"), hist = temp_path("h.csv");
  const std::string ref = temp_path("ref.png");
  CliRun r =
      run({"render", "circles", "--pattern", "hasselgren-f", "--size", "32x32", "-o", png,
           "--error", err, "--histogram", hist, "--reference-samples", "64", "--reference", ref});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("2 samples per pixel"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("RMSE"), std::string::npos);
  EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
  EXPECT_EQ(slurp(err).substr(1, 3), "PNG");
  EXPECT_EQ(slurp(ref).substr(1, 3), "PNG");
  std::istringstream lines(slurp(hist));
  std::string header;
  std::getline(lines, header);
  EXPECT_EQ(header, "deviation,count,contribution");
  r = run({"render", "spiral", "--generator", "jittered", "--samples", "4", "--filter",
           "gaussian-half", "--size", "16x16", "--json", "--reference-samples", "16"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto js = nlohmann::json::parse(r.out);
  EXPECT_GE(js["rmse"].get<double>(), 0.0);
  EXPECT_EQ(js["samples_per_pixel"], 4.0);
  r = run({"render", "teapot", "--pattern", "rgss"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown scene 'teapot'"), std::string::npos) << r.err;
  EXPECT_EQ(run({"render", "circles", "--generator", "jittered"}).code, 1);  // needs a filter
  EXPECT_EQ(run({"render", "circles", "--pattern", "rgss", "--size", "0x5"}).code, 1);
}

TEST(CliRender, SceneFilesViewsSsimAndTheCache) {
  const std::string scene = temp_path("scene.json"), cache = temp_path("cache");
  fs::remove_all(cache);  // an earlier run's entries (another cache version) are not this run's
  std::ofstream(scene) << R"({"background": 0, "shapes": [
      {"polygon": [[2, 2], [20, 4], [6, 18]], "grey": 1},
      {"circle": [14, 14], "radius": 4, "grey": 0.5}]})";
  const std::vector<std::string> args{"render",
                                      scene,
                                      "--pattern",
                                      "flipquad",
                                      "--size",
                                      "24x24",
                                      "--rotate",
                                      "15",
                                      "--scale",
                                      "1.2",
                                      "--translate",
                                      "1,-2",
                                      "--reference-samples",
                                      "64",
                                      "--cache",
                                      cache,
                                      "--json"};
  CliRun r = run(args);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto first = nlohmann::json::parse(r.out);
  EXPECT_GT(first["ssim"].get<double>(), 0.5);
  EXPECT_LT(first["ssim"].get<double>(), 1.0);
  EXPECT_EQ(std::distance(fs::directory_iterator(cache), fs::directory_iterator{}), 1);
  r = run(args);  // from the cache: the same figures
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out), first);
  r = run({"render", "spiral", "--pattern", "rgss", "--size", "8x8", "--no-cache", "--json",
           "--reference-samples", "4"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(nlohmann::json::parse(r.out)["ssim"].is_null());  // smaller than the window
  r = run({"render", scene, "--pattern", "rgss", "--translate", "1"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--translate: '1' is not X,Y"), std::string::npos) << r.err;
  r = run({"render", "checkerboard:horizon=7", "--pattern", "rgss"});
  EXPECT_NE(r.err.find("horizon = 7 is out of range"), std::string::npos) << r.err;
  r = run({"list"});
  EXPECT_NE(r.out.find("checkerboard:horizon=0.8,focal=1,eye=1,rotation=20"), std::string::npos);
}

TEST(CliRender, GridSheetWithItsErrorTable) {
  const std::string png = temp_path("sheet.png"), table = temp_path("sheet.md");
  CliRun r = run({"render",
                  "checkerboard",
                  "--grid",
                  "--size",
                  "16x12",
                  "--rows",
                  "regular@4",
                  "jittered@4",
                  "flipquad",
                  "--columns",
                  "box",
                  "gaussian-half",
                  "--zoom",
                  "2",
                  "-o",
                  png,
                  "--table",
                  table,
                  "--reference-samples",
                  "16",
                  "--no-cache"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(png).substr(1, 3), "PNG");
  const std::string md = slurp(table);
  EXPECT_NE(md.find("| regular@4 | box | 4 |"), std::string::npos) << md;
  EXPECT_NE(md.find("| flipquad | gaussian-half | 2 |"), std::string::npos) << md;
  EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), 2 + 2 + 6);  // heading, header, 6 cells
  r = run({"render", "checkerboard", "--grid", "--rows", "jittered@4", "--columns", "weights", "-o",
           temp_path("w.png"), "--no-cache"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("is a generator, which has no weights"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(temp_path("w.png")));
  r = run({"render", "checkerboard", "--grid", "--rows", "jittered@0", "-o", temp_path("z.png")});
  EXPECT_NE(r.err.find("--rows jittered@0"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace aapat
