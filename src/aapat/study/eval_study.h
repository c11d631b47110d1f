// What `aapat eval` reports of each pattern: E2 with its worst kernel and
// angle, n, optionally the E2 with weights optimized for the same positions
// and the per-angle profile of the worst kernel.
#pragma once

#include <optional>
#include <vector>

#include "aapat/core/metric.h"
#include "aapat/core/objective.h"
#include "aapat/io/json_report.h"

namespace aapat {

struct PatternEvaluation {
  PatternError error;
  double samples_per_pixel = 0;
  std::optional<double> e2_optimized_weights;
  std::vector<double> worst_profile;  // W(theta) E1(theta) of the worst kernel, when asked
};

std::vector<PatternEvaluation> evaluate_patterns(const Metric& metric,
                                                 const std::vector<Pattern>& patterns,
                                                 bool optimized_weights, bool profiles);

// The `aapat eval --json` document: the objective, its angle count and a row
// per pattern (pattern, family, n, e2, worst_angle_deg, worst_kernel,
// kernel_e2[, e2_optimized_weights]); the command's text table is printed
// from it and aapat.eval_report returns it.
JsonObject eval_json(const Objective& objective, int angles, const std::vector<Pattern>& patterns,
                     const std::vector<PatternEvaluation>& evaluations);

}  // namespace aapat
