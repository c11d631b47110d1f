#include "aapat/study/enumeration.h"

#include <fmt/format.h>

#include <algorithm>

#include "aapat/optimize/multistart.h"
#include "aapat/work/work_items.h"

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
  if (!(settings.rules.max_per_edge >= 0 && settings.rules.max_per_edge <= 8))
    throw ParameterError("max-per-edge",
                         fmt::format(" {}: expected 0 to 8", settings.rules.max_per_edge));
  Enumeration e;
  for (double n : settings.costs)
    for (const auto& c : enumerate_placements(n, settings.rules))
      e.rows.push_back({static_cast<int>(e.rows.size()) + 1, n, c, NAN, {}});
  if (!settings.optimize) return e;
  // One work item per configuration (work/work_items.h), its starts on the
  // cores of the process that runs it: configurations differ in cost by
  // orders of magnitude, so they are handed out one by one.
  const auto seeds_of = [&](const EnumerationRow& row) {
    const FamilySpec spec =
        parse_family(fmt::format("P(4,1+,{})", format_cost(row.n)), row.config.sites());
    return family_seeds(spec, SeedKind::kJittered, settings.seed, metric.filter());
  };
  const std::vector<std::string> results = run_work_items(
      static_cast<int>(e.rows.size()),
      [&](int i) {
        const MultiStartResult r =
            multistart(metric, settings.starts, settings.seed,
                       seeds_of(e.rows[static_cast<size_t>(i)]), OptimizerSettings{}, 0);
        ByteWriter w;
        w.put(r.starts[r.best].run.final_e2).put<int32_t>(r.starts[r.best].start);
        put_problem_values(w, r.best_problem);
        return w.take();
      },
      [&](int done, int total, const std::string& result) {
        if (progress)
          progress(done, total, fmt::format("E2 {:.4f}", ByteReader(result).get<double>()));
      });
  for (size_t i = 0; i < e.rows.size(); ++i) {
    EnumerationRow& row = e.rows[i];
    ByteReader r(results[i]);
    row.e2 = r.get<double>();
    Problem best = seeds_of(row)(r.get<int32_t>());
    get_problem_values(r, best);
    r.finish();
    row.best = pattern_of(best);
    row.best.name = fmt::format("P(4,1+,{})-config-{}", format_cost(row.n), row.id);
    row.best.description = fmt::format("placement {}", row.config.sites());
    row.best.provenance = {{"enumerate", fmt::format("configuration {}", row.id)},
                           {"placement", row.config.sites()},
                           {"filter", metric.filter().name()},
                           {"acuity", metric.acuity().name},
                           {"seed", std::to_string(settings.seed)},
                           {"starts", std::to_string(settings.starts)},
                           {"e2", fmt::format("{:.6f}", row.e2)}};
  }
  // Rank within each cost by E2.
  std::stable_sort(e.rows.begin(), e.rows.end(), [](const auto& a, const auto& b) {
    return a.n != b.n ? a.n < b.n : a.e2 < b.e2;
  });
  return e;
}

}  // namespace aapat
