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

JsonObject eval_json(const Objective& objective, int angles, const std::vector<Pattern>& patterns,
                     const std::vector<PatternEvaluation>& evaluations) {
  JsonObject rows = JsonObject::array();
  for (size_t i = 0; i < patterns.size(); ++i) {
    const PatternEvaluation& v = evaluations[i];
    rows.push_back({{"pattern", patterns[i].name},
                    {"family", family(patterns[i])},
                    {"n", v.samples_per_pixel},
                    {"e2", v.error.e2},
                    {"worst_angle_deg", v.error.worst_angle_deg},
                    {"worst_kernel", v.error.worst_kernel},
                    {"kernel_e2", v.error.kernel_e2}});
    if (v.e2_optimized_weights) rows.back()["e2_optimized_weights"] = *v.e2_optimized_weights;
  }
  JsonObject doc = json_report("eval");
  doc.update(objective_json(objective));
  doc["angles"] = angles;
  doc["rows"] = rows;
  return doc;
}

}  // namespace aapat
