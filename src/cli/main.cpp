#include <iostream>

#include "cli/app.h"

int main(int argc, char** argv) {
  return aapat::run_aapat(argc, argv, std::cout, std::cerr);
}
