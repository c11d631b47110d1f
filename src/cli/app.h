// The `aapat` command line: one subcommand per job. The entry point takes its
// streams so that tests run it in-process.
#pragma once

#include <iosfwd>

namespace aapat {

class WorkEngine;

// Exit codes (docs/cli.md): 0 success; 1 the job failed (bad input, an
// impossible request, a limit, a file that cannot be written); 2 the command
// line itself is wrong. Nothing else: every exception becomes a message.
inline constexpr int kExitOk = 0;
inline constexpr int kExitError = 1;
inline constexpr int kExitUsage = 2;

// `engine`: where the command's work items run (work/work_items.h); by
// default this process's cores. An MPI rank passes its engine (cli/process.h).
int run_aapat(int argc, const char* const* argv, std::ostream& out, std::ostream& err,
              WorkEngine* engine = nullptr);

// Where a command's warnings go (the run's error stream): a warning does not
// fail the command.
std::ostream& warnings();

}  // namespace aapat
