#include <iostream>

#include "cli/app.h"
#include "aapat/io/atomic_file.h"

int main(int argc, char** argv) {
  aapat::remove_temporaries_on_signals();
  return aapat::run_aapat(argc, argv, std::cout, std::cerr);
}
