// `aapat table3`: Laine-Aila Table 3 re-run. P(16,16,4) patterns (4x4 pixel
// tiles, 4x4 pixel kernels, 64 samples per kernel) drawn as jittered grids and
// Poisson-disk sets with Mitchell-Netravali weights h(x) h(y): min / avg / max
// E2 over many patterns, then the best optimized for weights only (Opt W) and
// from there for weights and positions (Opt W+P).
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <ostream>

#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"
#include "aapat/io/json_report.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/multistart.h"

namespace aapat {

Action add_table3_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("table3", "re-run Laine-Aila Table 3 (P(16,16,4) distributions)");
  struct Options {
    int patterns = 1000, iterations = 4000;
    uint64_t seed = 1;
    bool json = false;
    MetricOptions metric;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--patterns", o->patterns, "random patterns per distribution")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_option("--iterations", o->iterations, "optimizer iterations per stage")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000000));
  cmd->add_flag("--json", o->json, "print the numbers as JSON");
  o->metric.add_to(cmd);
  return [o](std::ostream& out) {
    const Metric metric = o->metric.make();
    const FamilySpec spec = parse_family("P(16,16,4)", "");
    struct Row {
      const char* name;
      SeedKind kind;
      double paper[5];  // Min, Avg, Max, Opt W, Opt W+P (Laine-Aila Table 3)
    };
    const Row rows[] = {{"jittered grid", SeedKind::kJittered, {0.423, 0.622, 0.907, 0.242, 0.169}},
                        {"Poisson disk", SeedKind::kPoisson, {0.346, 0.473, 0.782, 0.221, 0.161}}};
    JsonObject js = JsonObject::array();
    std::string table;
    for (const Row& row : rows) {
      double lo = INFINITY, hi = 0, sum = 0;
      Pattern best;
      {
        Progress bar(fmt::format("{:<13}", row.name));
        for (int i = 0; i < o->patterns; ++i) {
          auto rng = start_rng(o->seed, static_cast<uint64_t>(i));
          Pattern p = seed_pattern(spec, row.kind, rng, metric.filter());  // h(x) h(y) weights
          const double e2 = metric.evaluate(p).e2;
          sum += e2;
          hi = std::max(hi, e2);
          if (e2 < lo) {
            lo = e2;
            best = p;
          }
          if (i % 50 == 49 || i + 1 == o->patterns)
            bar.update(i + 1, o->patterns, fmt::format("min {:.3f}", lo));
        }
      }
      OptimizerSettings settings;
      settings.max_iterations = o->iterations;
      settings.weights_only = true;
      MultiStartResult w = multistart(
          metric, 1, o->seed, [&](int) { return problem_from_pattern(best); }, settings, 0);
      settings.weights_only = false;
      const Problem after_w = w.best_problem;
      MultiStartResult wp = multistart(
          metric, 1, o->seed, [&](int) { return after_w; }, settings, 0);
      const double ours[5] = {lo, sum / o->patterns, hi, w.starts[w.best].run.final_e2,
                              wp.starts[wp.best].run.final_e2};
      js.push_back(
          {{"distribution", row.name},
           {"min", ours[0]},
           {"avg", ours[1]},
           {"max", ours[2]},
           {"opt_w", ours[3]},
           {"opt_wp", ours[4]},
           {"paper", {row.paper[0], row.paper[1], row.paper[2], row.paper[3], row.paper[4]}}});
      table += fmt::format("{:<14}", row.name);
      for (int c = 0; c < 5; ++c) table += fmt::format("  {:.3f} ({:.3f})", ours[c], row.paper[c]);
      table += "\n";
    }
    if (o->json) {
      JsonObject doc = json_report("table3");
      doc.update(JsonObject{{"family", "P(16,16,4)"},
                            {"patterns", o->patterns},
                            {"seed", o->seed},
                            {"filter", metric.filter().name()},
                            {"acuity", metric.acuity().name},
                            {"rows", js}});
      out << json_text(doc);
      return;
    }
    out << fmt::format(
        "Laine-Aila Table 3 re-run: P(16,16,4), {} patterns per distribution, seed {}, filter {}, "
        "acuity {}\naapat (paper)   Min              Avg              Max              Opt W     "
        "       Opt W+P\n{}",
        o->patterns, o->seed, metric.filter().name(), metric.acuity().name, table);
  };
}

}  // namespace aapat
