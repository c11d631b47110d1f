#include "aapat/io/atomic_file.h"
#include "cli/process.h"

#include <csignal>

int main(int argc, char** argv) {
  aapat::remove_temporaries_on_signals();
  // A reader that has gone (`aapat list | head -1`) makes a write fail with
  // EPIPE, which the command reports (exit 1, a message), instead of a
  // silent death by SIGPIPE that a script could take for success of a kind.
  std::signal(SIGPIPE, SIG_IGN);
  return aapat::run_process(argc, argv);
}
