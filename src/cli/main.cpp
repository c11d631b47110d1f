#include "aapat/io/atomic_file.h"
#include "cli/process.h"

int main(int argc, char** argv) {
  aapat::remove_temporaries_on_signals();
  return aapat::run_process(argc, argv);
}
