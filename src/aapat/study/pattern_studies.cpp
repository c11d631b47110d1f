#include "aapat/study/pattern_studies.h"

#include "aapat/core/objective.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/lattice.h"
#include "aapat/io/pattern_json.h"
#include "aapat/optimize/descent.h"

namespace aapat {

SnapResult snap_study(const Metric& metric, const Pattern& before, int steps, bool optimize_weights,
                      bool nonnegative) {
  SnapResult r;
  r.snapped = snap_to_lattice(before, steps);
  r.snapped.name = fmt::format("{}-lattice{}", before.name, steps);
  r.e2_before = metric.evaluate(before).e2;
  r.e2_snapped = metric.evaluate(r.snapped).e2;
  if (optimize_weights) {
    r.snapped = with_optimized_weights(metric, r.snapped, nonnegative);
    r.e2_optimized_weights = metric.evaluate(r.snapped).e2;
  }
  for (size_t k = 0; k < before.sets.size(); ++k)
    for (size_t i = 0; i < before.sets[k].size(); ++i)
      r.largest_move =
          std::max(r.largest_move, std::hypot(r.snapped.sets[k][i].x - before.sets[k][i].x,
                                              r.snapped.sets[k][i].y - before.sets[k][i].y));
  return r;
}

std::vector<Table2Row> table2(const AnimationSettings& settings, const ReferenceSource& references,
                              const StudyProgress& progress) {
  std::vector<Table2Row> rows = {
      {"centroid", "Centroid sampling", 0, 0, 0, 1.256, 9.810, 131},
      {"diagonal-hasselgren", "Diagonal", 0, 0, 0, 0.692, 6.500, 126},
      {"hasselgren-a", "Scheme A (FLIPTRI)", 0, 0, 0, 0.554, 7.548, 159},
      {"hasselgren-b", "Scheme B", 0, 0, 0, 0.531, 5.139, 114},
      {"hasselgren-c", "Scheme C", 0, 0, 0, 0.527, 4.830, 107},
      {"hasselgren-d", "Scheme D", 0, 0, 0, 0.497, 5.000, 107},
      {"hasselgren-e", "Scheme E", 0, 0, 0, 0.488, 4.574, 108},
      {"quincunx-hasselgren", "Quincunx", 0, 0, 0, 0.484, 4.400, 95},
      {"hasselgren-f", "Scheme F (FLIPQUAD)", 0, 0, 0, 0.359, 3.759, 76}};
  const Metric metric = named_objective(kPapersObjective).metric();  // E2 as the paper has it
  int done = 0;
  for (Table2Row& r : rows) {
    Sampling s;
    s.pattern = resolve_pattern(r.pattern);
    const ImageError e = animate(settings, s, std::nullopt, {}, references).total;
    r.e2 = metric.evaluate(*s.pattern).e2;
    r.rmse = e.rmse;
    r.max_deviation = e.max_deviation;
    if (progress) progress(++done, static_cast<int>(rows.size()), r.pattern);
  }
  return rows;
}

}  // namespace aapat
