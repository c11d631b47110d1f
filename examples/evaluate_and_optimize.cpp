// Evaluates the classic 4-sample patterns with the Laine-Aila E2 metric, then
// optimizes a 4-sample pattern from random starts and prints it: the library
// used from an installed package, without the command line.
#include <aapat/core/acuity.h>
#include <aapat/core/filter_catalog.h>
#include <aapat/core/metric.h>
#include <aapat/core/objective.h>
#include <aapat/generate/catalog.h>
#include <aapat/study/optimize_run.h>
#include <aapat/version.h>

#include <cstdio>

int main() {
  using namespace aapat;
  // The papers' objective, under which their tables are reproduced.
  const Metric metric = named_objective(kPapersObjective).metric();
  std::printf("aapat %s\n", AAPAT_VERSION);
  for (const char* name : {"box2x2", "rgss", "flipquad"})
    std::printf("%-10s E2 %.4f\n", name, metric.evaluate(catalog_pattern(name)).e2);

  OptimizeRunSettings settings;
  settings.family = "P(1,1,4)";
  settings.starts = 16;
  settings.seed = 1;
  settings.strictly_inside = false;  // the papers' closed pixel
  const OptimizeRunResult r = optimize_run(metric, settings);
  std::printf("optimized %s: E2 %.4f (Laine-Aila Table 2: 0.359)\n", r.description.c_str(),
              r.best_start().run.final_e2);
  for (const Vec2& s : r.best.sets[0]) std::printf("  %9.5f %9.5f\n", s.x, s.y);
  // The published optimum of P(1,1,4) is E2 0.3587; say so if it was missed.
  return r.best_start().run.final_e2 < 0.36 ? 0 : 1;
}
