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
  EXPECT_EQ(commands, 22);
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

// --threads before the command limits every parallel step; the output is the
// same bytes on any count.
TEST(Cli, GlobalThreadsGiveTheSameOutput) {
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

}  // namespace
}  // namespace aapat
