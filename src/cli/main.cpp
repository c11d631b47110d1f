#include <iostream>

#include "aapat/io/atomic_file.h"
#include "cli/app.h"

int main(int argc, char** argv) {
  aapat::remove_temporaries_on_signals();
  return aapat::run_aapat(argc, argv, std::cout, std::cerr);
}
