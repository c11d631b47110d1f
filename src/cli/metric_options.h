// The options every command that evaluates or optimizes E2 shares:
// --objective NAME|SPEC and its component overrides --filter, --acuity, --norm.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>

#include "aapat/core/metric.h"
#include "aapat/core/objective.h"

namespace aapat {

struct MetricOptions {
  std::string objective;
  std::string filter, acuity, norm;  // empty: the objective's

  // `default_objective`: kDefaultObjective everywhere but the paper
  // reproductions, which default to the papers' objective.
  void add_to(CLI::App* cmd, std::string_view default_objective = kDefaultObjective);
  Objective resolve() const;
  Metric make() const { return resolve().metric(); }
};

}  // namespace aapat
