#include "aapat/core/lattice.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/pattern_json.h"
#include "aapat/study/perceptual_objective.h"
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

TEST(CliEval, EvalJsonHasTheDocumentedKeys) {
  const CliRun r = run({"eval", "flipquad", "centroid", "--objective", "laine-aila", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["command"], "eval");  // docs/json.md: command, schema, settings, rows
  EXPECT_EQ(doc["schema"], 1);
  EXPECT_EQ(doc["objective"], "laine-aila");
  EXPECT_EQ(doc["acuity"], "laine-aila");
  EXPECT_EQ(doc["norm"], "inf");
  const auto& rows = doc["rows"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["pattern"], "flipquad");
  EXPECT_EQ(rows[0]["family"], "P(4,1+,2)");
  EXPECT_EQ(rows[0]["n"], 2.0);
  EXPECT_NEAR(rows[0]["e2"].get<double>(), 0.364, 0.001);  // Laine-Aila Table 2
  EXPECT_EQ(rows[1]["worst_angle_deg"], 0.0);
  EXPECT_NEAR(rows[1]["e2"].get<double>(), 1.256, 0.001);  // Hasselgren Table 2
}

TEST(CliEval, EvalTableAndOtherFiltersAndNorms) {
  const CliRun r = run({"eval", "rgss", "--filter", "gaussian:sigma=0.5", "--acuity",
                        "uniform:step=5", "--norm", "4"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("objective (filter gaussian:sigma=0.5,radius=1.5, acuity "
                       "uniform:step=5,weight=1, norm 4), 36 angles"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("rgss"), std::string::npos);
}

TEST(CliEval, ProfileWritesSvgAndCsv) {
  const std::string svg = temp_path("profile.svg"), csv = temp_path("profile.csv");
  ASSERT_EQ(run({"eval", "flipquad", "rgss", "--profile", svg}).code, 0);
  ASSERT_EQ(run({"eval", "flipquad", "rgss", "--profile", csv}).code, 0);
  std::ifstream s(svg), c(csv);
  std::stringstream svg_text, csv_text;
  svg_text << s.rdbuf();
  csv_text << c.rdbuf();
  EXPECT_NE(svg_text.str().find("<svg"), std::string::npos);
  EXPECT_NE(svg_text.str().find("flipquad"), std::string::npos);
  std::string header;
  std::getline(csv_text, header);
  EXPECT_EQ(header, "edge_angle_deg,acuity,flipquad,rgss");
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

// A pattern file named like a catalog entry: the catalog's own samples keep
// the name (`show rgss -o`), other samples are read under the file's name.
TEST(CliEval, APatternFileNamedLikeACatalogEntryIsReadUnderItsOwnName) {
  const std::string same = testing::temp_path("same.json"),
                    edited = testing::temp_path("mine.json");
  ASSERT_EQ(testing::run({"show", "rgss", "-o", same}).code, 0);
  nlohmann::json doc = nlohmann::json::parse(testing::slurp(same));
  doc["sets"][0][0][0] = 0.1;  // one sample moved
  std::ofstream(edited) << doc.dump();
  ::testing::internal::CaptureStderr();
  const auto r = testing::run({"eval", same, edited, "--json"});
  const std::string warned = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  EXPECT_EQ(rows[0]["pattern"], "rgss");
  EXPECT_EQ(rows[1]["pattern"], "mine");
  EXPECT_NE(warned.find("pattern file '" + edited + "' is named 'rgss'"), std::string::npos)
      << warned;
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

// The command ends in exit 1 with a message that says `says`.
void fails(const std::vector<std::string>& args, const std::string& says) {
  const testing::CliRun bad = testing::run(args);
  EXPECT_EQ(bad.code, 1) << args[1];
  EXPECT_NE(bad.err.find(says), std::string::npos) << bad.err;
}

// The perceptual objective on the command line: eval prints its value and
// each kind's FLIP (the library's, to the digit), refine writes a pattern no
// worse than its start, and a bad spec or an E2-only flag ends in exit 1
// naming the problem.
TEST(CliPerceptual, EvalRefineAndBadSpecs) {
  const std::string spec = "perceptual:angles=2,patch=16,reference=16";
  const testing::CliRun e = testing::run({"eval", "msaa-4", "--objective", spec, "--json"});
  ASSERT_EQ(e.code, 0) << e.err;
  const auto doc = nlohmann::json::parse(e.out);
  const PerceptualObjective o(parse_perceptual(spec));
  EXPECT_EQ(doc["rows"][0]["perceptual"].get<double>(), o(catalog_pattern("msaa-4")));
  EXPECT_EQ(doc["rows"][0]["kinds"].size(), 3u);
  const std::string out = testing::temp_path("refined.json");
  const testing::CliRun r = testing::run(
      {"--quiet", "refine", "msaa-4", "-O", spec, "--max-tries", "20", "-o", out, "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto refined = nlohmann::json::parse(r.out);
  EXPECT_LE(refined["after"].get<double>(), refined["before"].get<double>());
  EXPECT_EQ(o(resolve_pattern(out)), refined["after"].get<double>());
  EXPECT_EQ(resolve_pattern(out).name, "msaa-4-perceptual");
  std::filesystem::remove(out);
  fails({"eval", "msaa-4", "--objective", "perceptual:ppd=0.5"}, "ppd");
  fails({"eval", "msaa-4", "--objective", "perceptual:edge=0,line=0,thin=0,dot=0"},
        "no primitives");
  fails({"eval", "msaa-4", "--objective", "perceptual:background=inf"}, "background");
  fails({"eval", "msaa-4", "--objective", "perceptual", "--acuity", "laine-aila"}, "--acuity");
  fails({"optimize", "--family", "P(1,1,4)", "--objective", "perceptual"}, "aapat refine");
  fails({"refine", "msaa-4", "-O", "recommended"}, "perceptual");
}

// refine on scenes: the objective is the rendered FLIP that study --compare
// reports for the same scenes (to the digit, before and after), on an API's
// lattice when asked; bad scenes, measures and APIs end in exit 1 naming them.
TEST(CliRefine, OnScenesAndOnALattice) {
  const std::vector<std::string> scenes = {
      "--scenes", "spiral", "--size", "12", "--reference-samples", "16"};
  const std::string out = testing::temp_path("refined-on-scenes.json");
  std::vector<std::string> args = {"--quiet", "refine",      "rgss", "--max-tries", "8",
                                   "--api",   "d3d12-tier1", "-o",   out,           "--json"};
  args.insert(args.end(), scenes.begin(), scenes.end());
  const testing::CliRun r = testing::run(args);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto doc = nlohmann::json::parse(r.out);
  EXPECT_EQ(doc["api"], "d3d12-tier1");
  EXPECT_LE(doc["after"].get<double>(), doc["before"].get<double>());
  const Pattern refined = resolve_pattern(out);
  EXPECT_EQ(refined.name, "rgss-rendered");
  EXPECT_EQ(off_lattice_sample(refined, kLatticeSteps), "");
  const auto mean_flip = [&](const std::string& pattern) {
    std::vector<std::string> compare = {"--quiet", "study", "--compare", pattern, "--json"};
    compare.insert(compare.end(), scenes.begin(), scenes.end());
    const testing::CliRun c = testing::run(compare);
    EXPECT_EQ(c.code, 0) << c.err;
    const auto d = nlohmann::json::parse(c.out);
    double sum = 0;
    for (const auto& per_scene : d["patterns"][0]["measures"]) sum += per_scene[4].get<double>();
    return sum / double(d["patterns"][0]["measures"].size());
  };
  EXPECT_NEAR(mean_flip("rgss"), doc["before"].get<double>(), 1e-15);
  EXPECT_NEAR(mean_flip(out), doc["after"].get<double>(), 1e-15);
  std::filesystem::remove(out);
  fails({"refine", "rgss", "--scenes", "nosuch-scene"}, "nosuch-scene");
  fails({"refine", "rgss", "--scenes", "spiral", "--measure", "psnr"}, "measure");
  fails({"refine", "rgss", "--scenes", "spiral", "--size", "4"}, "size");
  fails({"refine", "rgss", "--api", "nosuch", "--max-tries", "2"}, "nosuch");
  fails({"refine", "aapat-16", "--api", "metal", "--max-tries", "2"}, "metal");
  const testing::CliRun both =
      testing::run({"refine", "rgss", "--scenes", "spiral", "-O", "perceptual"});
  EXPECT_EQ(both.code, 2);  // a usage error, as CLI11 reports them
  EXPECT_NE(both.err.find("excludes"), std::string::npos) << both.err;
}

}  // namespace
}  // namespace aapat
