// The options every metric-driven command shares: --filter, --acuity, --norm.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "aapat/core/metric.h"

namespace aapat {

struct MetricOptions {
  std::string filter = "mitchell";
  std::string acuity = "laine-aila";
  std::string norm = "inf";

  void add_to(CLI::App* cmd);
  Metric make() const;
};

}  // namespace aapat
