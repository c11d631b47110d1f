#include "aapat/study/eval_study.h"

#include "aapat/optimize/descent.h"

namespace aapat {

std::vector<PatternEvaluation> evaluate_patterns(const Metric& metric,
                                                 const std::vector<Pattern>& patterns,
                                                 bool optimized_weights, bool profiles) {
  std::vector<PatternEvaluation> out;
  for (const Pattern& p : patterns) {
    PatternEvaluation e{metric.evaluate(p), samples_per_pixel(p), std::nullopt, {}};
    if (optimized_weights)
      e.e2_optimized_weights = metric.evaluate(with_optimized_weights(metric, p, false)).e2;
    if (profiles) e.worst_profile = metric.profile(make_kernel(p, e.error.worst_kernel));
    out.push_back(std::move(e));
  }
  return out;
}

}  // namespace aapat
