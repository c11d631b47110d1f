// The accumulation model's options, shared by `aapat sequence eval` and
// `aapat optimize --sequence`: --model, --alpha, --window, --resolve.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "aapat/temporal/model/accumulation.h"

namespace aapat {

struct ModelOptions {
  std::string model{kDefaultAccumulation}, resolve;
  double alpha = kDefaultAlpha;
  int window = 0;

  void add_to(CLI::App* cmd);
  // Throws Error naming the flag of a setting out of range.
  Accumulation make() const;
  // "EMA alpha 0.1, gaussian:... resolve", for reports.
  std::string text() const;
};

}  // namespace aapat
