#include "aapat/study/enumeration.h"

#include <fmt/format.h>

#include <algorithm>

#include "aapat/optimize/multistart.h"

namespace aapat {

int Enumeration::count(double n) const {
  return static_cast<int>(
      std::count_if(rows.begin(), rows.end(), [&](const EnumerationRow& r) { return r.n == n; }));
}

const EnumerationRow* Enumeration::best(double n) const {
  for (const EnumerationRow& r : rows)
    if (r.n == n) return &r;
  return nullptr;
}

Enumeration enumerate_study(const Metric& metric, const EnumerationSettings& settings,
                            const StudyProgress& progress) {
  if (!(settings.starts >= 1 && settings.starts <= 100000))
    throw ParameterError("starts", fmt::format(" {}: expected 1 to 100000", settings.starts));
  Enumeration e;
  for (double n : settings.costs)
    for (const auto& c : enumerate_placements(n, settings.rules))
      e.rows.push_back({static_cast<int>(e.rows.size()) + 1, n, c, NAN, {}});
  if (!settings.optimize) return e;
  for (size_t i = 0; i < e.rows.size(); ++i) {
    EnumerationRow& row = e.rows[i];
    const FamilySpec spec =
        parse_family(fmt::format("P(4,1+,{})", format_cost(row.n)), row.config.sites());
    const MultiStartResult r =
        multistart(metric, settings.starts, settings.seed,
                   family_seeds(spec, SeedKind::kJittered, settings.seed, metric.filter()),
                   OptimizerSettings{}, 0);
    row.e2 = r.starts[r.best].run.final_e2;
    row.best = pattern_of(r.best_problem);
    row.best.name = fmt::format("P(4,1+,{})-config-{}", format_cost(row.n), row.id);
    row.best.description = fmt::format("placement {}", row.config.sites());
    row.best.provenance = {{"enumerate", fmt::format("configuration {}", row.id)},
                           {"placement", row.config.sites()},
                           {"filter", metric.filter().name()},
                           {"acuity", metric.acuity().name},
                           {"seed", std::to_string(settings.seed)},
                           {"starts", std::to_string(settings.starts)},
                           {"e2", fmt::format("{:.6f}", row.e2)}};
    if (progress)
      progress(static_cast<int>(i + 1), static_cast<int>(e.rows.size()),
               fmt::format("n = {} E2 {:.4f}", format_cost(row.n), row.e2));
  }
  // Rank within each cost by E2.
  std::stable_sort(e.rows.begin(), e.rows.end(), [](const auto& a, const auto& b) {
    return a.n != b.n ? a.n < b.n : a.e2 < b.e2;
  });
  return e;
}

}  // namespace aapat
