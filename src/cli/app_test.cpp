#include "cli/app.h"
#include "cli/animation_options.h"
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

TEST(Cli, EvalJsonHasTheDocumentedKeys) {
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

TEST(Cli, EvalTableAndOtherFiltersAndNorms) {
  const CliRun r = run({"eval", "rgss", "--filter", "gaussian:sigma=0.5", "--acuity",
                        "uniform:step=5", "--norm", "4"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("objective (filter gaussian:sigma=0.5,radius=1.5, acuity "
                       "uniform:step=5,weight=1, norm 4), 36 angles"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("rgss"), std::string::npos);
}

TEST(Cli, ProfileWritesSvgAndCsv) {
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

TEST(Cli, ShowWritesDrawingAndPatternFile) {
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

TEST(Cli, ListNamesCatalogFiltersAndTables) {
  const CliRun r = run({"list"});
  ASSERT_EQ(r.code, 0);
  for (const char* s : {"hasselgren-f", "msaa-16", "grid-NxN", "mitchell:b=1/3,c=1/3",
                        "lanczos:lobes=3", "laine-aila", "uniform:step=STEP"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

// A run builds only the command it names: every command of the overview
// is found by its name, alone, and its help names it.
TEST(Cli, EveryCommandOfTheOverviewRunsByItsName) {
  const CliRun overview = run({"--help"});
  ASSERT_EQ(overview.code, 0);
  const size_t list = overview.out.find("Subcommands:");
  ASSERT_NE(list, std::string::npos) << overview.out;
  std::istringstream lines(overview.out.substr(list));
  std::string line;
  std::getline(lines, line);
  int commands = 0;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string name;
    if (!(words >> name)) continue;
    const CliRun help = run({"--threads", "1", name, "--help"});
    EXPECT_EQ(help.code, 0) << name << ": " << help.err;
    EXPECT_NE(help.out.find("Usage: aapat " + name), std::string::npos) << help.out;
    ++commands;
  }
  EXPECT_EQ(commands, 21);
}

// The mistakes a new user makes first are named, with the nearest name.
TEST(Cli, MistakesNameWhatWasMeant) {
  CliRun r = run({"evl", "rgss"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown command 'evl' (did you mean 'eval'?)"), std::string::npos) << r.err;
  r = run({"eval", "rgs"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown pattern 'rgs' (did you mean 'rgss'?)"), std::string::npos);
  EXPECT_NE(r.err.find("aapat-shared-2"), std::string::npos) << r.err;  // the aapat names too
  r = run({"sequence", "eval", "aapat-taa8"});
  EXPECT_NE(r.err.find("did you mean 'aapat-taa-8'?"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("halton"), std::string::npos) << r.err;
  const std::string spaces = temp_path("spaces.csv");
  std::ofstream(spaces) << "0.1 0.2\n";
  r = run({"discrepancy", spaces});
  EXPECT_NE(r.err.find("separates its numbers by spaces"), std::string::npos) << r.err;
  r = run({"eval", "flipquad", "--objective", "laine-aila", "--filter", "mitchel"});
  EXPECT_NE(r.err.find("did you mean 'mitchell'?"), std::string::npos) << r.err;
  r = run({"render", "circles", "--pattern", "rgss", "--size", "16", "-o", temp_path("c.png")});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("circles 16x16"), std::string::npos) << r.out;  // --size N is N x N
  EXPECT_NE(r.out.find("add --measure"), std::string::npos) << r.out;
}

TEST(Cli, BadInputGivesAClearErrorAndNonZeroExit) {
  CliRun r = run({"eval", "nosuch"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("aapat: error: unknown pattern 'nosuch'"), std::string::npos) << r.err;
  r = run({"eval", "flipquad", "--filter", "mitchel"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("unknown filter 'mitchel'"), std::string::npos);
  r = run({"eval", "flipquad", "--norm", "nan"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--norm: 'nan' is not a finite number"), std::string::npos) << r.err;
  r = run({"eval", "flipquad", "--norm", "0.5"});
  EXPECT_EQ(r.code, 1);
  r = run({"eval", "flipquad", "--profile", "x.png"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--profile: 'x.png' must end in .svg or .csv"), std::string::npos);
  r = run({"frobnicate"});
  EXPECT_NE(r.code, 0);
  r = run({"eval"});
  EXPECT_NE(r.code, 0);
}

TEST(Cli, NoOutputFileOnError) {
  const std::string bad = temp_path("bad.json"), out = temp_path("never.svg");
  std::ofstream(bad) << "{\"format\": \"aapat-pattern\"";
  const CliRun r = run({"show", bad, "-o", out});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("not valid JSON"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // A folder that does not exist: an error, and no temporary left behind.
  const std::string missing = temp_path("no_such_dir/p.svg");
  EXPECT_EQ(run({"show", "rgss", "-o", missing}).code, 1);
  EXPECT_FALSE(fs::exists(fs::path(missing).parent_path()));
}

TEST(Cli, AnExistingFileIsReplacedWhole) {
  const std::string path = temp_path("replace.svg");
  std::ofstream(path) << std::string(100000, 'x');
  ASSERT_EQ(run({"show", "centroid", "-o", path}).code, 0);
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_EQ(s.str().find('x' + std::string(10, 'x')), std::string::npos);
  EXPECT_TRUE(s.str().ends_with("</svg>\n"));
  for (const auto& e : fs::directory_iterator(fs::path(path).parent_path()))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

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

// Laine-Aila Table 3's shape on a small run: the best of many random patterns
// improves with optimized weights (a convex problem) and again with positions.
TEST(CliTable3, OptimizedColumnsImproveOnTheBestPattern) {
  const CliRun r = run({"table3", "--patterns", "24", "--iterations", "150", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    EXPECT_LE(row["min"].get<double>(), row["avg"].get<double>());
    EXPECT_LE(row["avg"].get<double>(), row["max"].get<double>());
    EXPECT_LT(row["opt_w"].get<double>(), row["min"].get<double>());
    EXPECT_LE(row["opt_wp"].get<double>(), row["opt_w"].get<double>());
  }
  // Poisson disk beats jittered on average, as in the paper (0.473 vs 0.622).
  EXPECT_LT(rows[1]["avg"].get<double>(), rows[0]["avg"].get<double>());
}

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

namespace aapat {
namespace {

// Hasselgren Table 2: the best configuration of each cost reaches the
// published E2 of schemes A, C, E and F (to the paper's rounding), with the
// same structure: a corner and two edges off it (A), two corners and two
// edges (C), a corner and three edges (E), one sample on each edge (F).
TEST(CliEnumerate, BestPerCostReachesThePublishedSchemes) {
  const CliRun r =
      run({"enumerate", "--optimize", "--starts", "8", "--objective", "laine-aila", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out)["rows"];
  ASSERT_EQ(rows.size(), 85u);
  const std::map<double, std::pair<double, std::string>> expected = {
      {1.25, {0.554, "top-left,bottom,right"}},
      {1.5, {0.527, "top-right,top-left,bottom,left"}},
      {1.75, {0.488, "top-left,bottom,right,left"}},
      {2.0, {0.359, "bottom,right,top,left"}}};
  std::map<double, nlohmann::json> best;
  for (const auto& row : rows)  // ranked: the first row of each n is its best
    if (!best.count(row["n"].get<double>())) best[row["n"].get<double>()] = row;
  for (const auto& [n, e] : expected) {
    EXPECT_LT(best[n]["e2"].get<double>(), e.first + 0.0005) << n;
    EXPECT_EQ(best[n]["placement"], e.second) << n;
  }
}

TEST(CliEnumerate, CountsWithoutOptimizing) {
  CliRun r = run({"enumerate", "--cost", "1,1.25,1.5,1.75,2"});
  ASSERT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("total       94"), std::string::npos) << r.out;
  r = run({"enumerate", "--cost", "1.3"});
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("--cost: 1.3 is not a multiple of 1/4"), std::string::npos) << r.err;
  r = run({"enumerate", "--gallery", temp_path("g.svg")});
  EXPECT_EQ(r.code, 1);
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

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

namespace aapat {
namespace {

TEST(CliPoints, GenerateWritesCsvAndPatternFiles) {
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

TEST(CliPoints, DiscrepancyReportsAllThree) {
  const CliRun r = run({"discrepancy", "regular", "--n", "16", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_NEAR(d["star_upper"].get<double>(), 1 - std::pow(1 - 1.0 / 8, 2), 1e-12);  // closed form
  EXPECT_TRUE(d["star_exact"].get<bool>());
  EXPECT_GT(d["edge"].get<double>(), 0.0);
  EXPECT_EQ(run({"discrepancy", "no-such"}).code, 1);
  const std::string bad = temp_path("bad.csv");
  std::ofstream(bad) << "0.5,0.5\n1.5,0.2\n";
  const CliRun e = run({"discrepancy", bad});
  EXPECT_EQ(e.code, 1);
  EXPECT_NE(e.err.find("line 2: (1.5, 0.2) lies outside the unit square"), std::string::npos)
      << e.err;
}

TEST(CliPoints, DiscrepancyComputesOnlyTheMeasuresAsked) {
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

// --threads before the command limits every parallel step; the output is the
// same bytes on any count.
TEST(CliPoints, GlobalThreadsGiveTheSameOutput) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"discrepancy", "halton", "--n", "5000", "--json"},
        {"spectrum", "jittered", "--n", "256", "--size", "32", "--fast", "--json"}}) {
    std::vector<std::string> one{"--threads", "1"};
    one.insert(one.end(), args.begin(), args.end());
    const CliRun a = run(one), b = run(args);
    ASSERT_EQ(a.code, 0) << a.err;
    EXPECT_EQ(a.out, b.out);
  }
  EXPECT_EQ(run({"--threads", "-1", "list"}).code, 2);
}

// --progress-lines: a line on stderr per tenth of the job although stderr is
// not a terminal here, the same output, and only for that command: the next
// one, without it, prints nothing on stderr (not a terminal).
TEST(Cli, ProgressLinesAreForOneCommandAndChangeNoOutput) {
  const std::vector<std::string> args{"optimize", "--sequence", "4", "--starts",
                                      "2",        "--seed",     "1"};
  std::vector<std::string> lines_args{"--progress-lines"};
  lines_args.insert(lines_args.end(), args.begin(), args.end());
  ::testing::internal::CaptureStderr();
  const CliRun with = run(lines_args);
  const std::string lines = ::testing::internal::GetCapturedStderr();
  ::testing::internal::CaptureStderr();
  const CliRun without = run(args);
  const std::string none = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(with.code, 0) << with.err;
  EXPECT_EQ(with.out, without.out);
  EXPECT_NE(lines.find("sequence: 1/2 best J"), std::string::npos) << lines;
  EXPECT_NE(lines.find("sequence: 2/2 best J"), std::string::npos) << lines;
  EXPECT_EQ(none, "");
}

// --fast: the non-uniform FFT, its bound in the JSON, its radial profile the
// exact one's within that bound; an odd size is refused by name.
TEST(CliPoints, FastSpectrumMatchesTheExactOneWithinItsBound) {
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

TEST(CliPoints, SpectrumWritesImageRadialProfileAndOneDimensionalPlot) {
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

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

TEST(CliPoints, TilesAndOneDimensionalComparison) {
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

namespace aapat {
namespace {

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

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

// Hasselgren Table 2's ordering on a small translating circle: centroid
// sampling deviates most, FLIPQUAD (scheme F) least of these three.
TEST(CliAnimate, TranslatingCircleOrdersThePatternsAsThePaper) {
  auto rmse = [](const char* pattern) {
    const CliRun r = run({"animate", "circle", "--pattern", pattern, "--size", "24", "--frames",
                          "6", "--reference-samples", "64", "--json"});
    EXPECT_EQ(r.code, 0) << r.err;
    return nlohmann::json::parse(r.out)["rmse"].get<double>();
  };
  const double centroid = rmse("centroid"), fliptri = rmse("hasselgren-a"),
               flipquad = rmse("hasselgren-f");
  EXPECT_GT(centroid, fliptri);
  EXPECT_GT(fliptri, flipquad);
  const std::string dir = temp_path("frames");
  ASSERT_EQ(run({"animate", "triangle", "--pattern", "rgss", "--size", "16", "--frames", "3",
                 "--reference-samples", "16", "--frames-dir", dir})
                .code,
            0);
  EXPECT_TRUE(fs::exists(dir + "/frame-0002.png"));
  EXPECT_EQ(run({"animate", "square", "--pattern", "rgss"}).code, 1);
}

// Frame files sort in frame order for any count: 4 digits up to 10,000
// frames, then as many as the last frame needs.
TEST(CliAnimate, FrameNamesSortForAnyCount) {
  EXPECT_EQ(frame_digits(1), 4);
  EXPECT_EQ(frame_digits(10000), 4);  // frame-9999 is the last
  EXPECT_EQ(frame_digits(10001), 5);  // frame-10000 needs frame-00000 .. before it
  EXPECT_EQ(frame_digits(1000001), 7);
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

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

TEST(CliAnimate, GifOfTheFrames) {
  const std::string gif = temp_path("a.gif");
  const CliRun r = run({"animate", "circle", "--pattern", "rgss", "--size", "12", "--frames", "3",
                        "--reference-samples", "4", "--gif", gif, "--no-cache"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(slurp(gif).substr(0, 6), "GIF89a");
  EXPECT_EQ(run({"animate", "circle", "--pattern", "rgss", "--gif", temp_path("a.png")}).code, 1);
  if (std::system("command -v ffmpeg >/dev/null 2>&1") != 0) {
    const CliRun m = run({"animate", "circle", "--pattern", "rgss", "--size", "12", "--frames", "2",
                          "--reference-samples", "4", "--mp4", temp_path("a.mp4")});
    EXPECT_EQ(m.code, 1);
    EXPECT_NE(m.err.find("needs ffmpeg on the PATH"), std::string::npos) << m.err;
    EXPECT_FALSE(fs::exists(temp_path("a.mp4")));
  }
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

TEST(CliHardware, SnapExportImportRoundTrip) {
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

TEST(CliHardware, LatticeOptimizationAndOptimizedWeights) {
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
