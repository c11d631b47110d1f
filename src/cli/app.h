// The `aapat` command line: one subcommand per job. The entry point takes its
// streams so that tests run it in-process.
#pragma once

#include <iosfwd>

namespace aapat {

int run_aapat(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace aapat
