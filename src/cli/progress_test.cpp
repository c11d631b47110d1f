// Progress wherever stderr goes: off a terminal, a long command writes lines
// (at most one every few seconds; AAPAT_PROGRESS_SECONDS=0 here, so that a
// short command shows them), and --quiet writes none.
#include "cli/progress.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "testing/cli_run.h"

namespace aapat {
namespace {

using testing::run;

std::string progress_of(const std::vector<std::string>& args) {
  ::testing::internal::CaptureStderr();
  const testing::CliRun r = run(args);
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(r.code, 0) << r.err;
  return err;
}

TEST(Progress, LinesOffATerminalAndNoneWhenQuiet) {
  ::setenv("AAPAT_PROGRESS_SECONDS", "0", 1);
  // Nine configurations, two starts each: a short job (the ASan build runs it).
  const std::vector<std::string> command = {"enumerate", "--optimize", "--objective", "laine-aila",
                                            "--starts",  "2",          "--cost",      "1.25"};
  const std::string lines = progress_of(command);
  EXPECT_NE(lines.find("enumerate: 1/9 E2"), std::string::npos) << lines;
  EXPECT_NE(lines.find("enumerate: 9/9"), std::string::npos) << lines;
  std::vector<std::string> quiet = command;
  quiet.insert(quiet.begin(), "--quiet");
  EXPECT_EQ(progress_of(quiet), "");
  ::unsetenv("AAPAT_PROGRESS_SECONDS");
}

}  // namespace
}  // namespace aapat
