// `aapat table3`: Laine-Aila Table 3 re-run. P(16,16,4) patterns (4x4 pixel
// tiles, 4x4 pixel kernels, 64 samples per kernel) drawn as jittered grids and
// Poisson-disk sets with Mitchell-Netravali weights h(x) h(y): min / avg / max
// E2 over many patterns, then the best optimized for weights only (Opt W) and
// from there for weights and positions (Opt W+P).
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/study/optimize_run.h"
#include "aapat/study/paper_tables.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"

namespace aapat {

namespace {

struct Table3Options {
  int patterns = 1000, iterations = 4000;
  uint64_t seed = 1;
  std::string method = "descent";
  bool json = false;
  MetricOptions metric;
};

void run_table3(Table3Options& o, std::ostream& out) {
  const Objective objective = o.metric.resolve();
  const Metric metric = objective.metric();
  std::vector<Table3Row> rows;
  {
    Progress bar("table3");
    rows =
        table3(metric, {o.patterns, o.iterations, o.seed, parse_method(o.method)}, bar.callback());
  }
  if (o.json) {
    JsonObject js = JsonObject::array();
    for (const Table3Row& r : rows)
      js.push_back({{"distribution", r.distribution},
                    {"min", r.e2[0]},
                    {"avg", r.e2[1]},
                    {"max", r.e2[2]},
                    {"opt_w", r.e2[3]},
                    {"opt_wp", r.e2[4]},
                    {"paper", r.paper}});
    JsonObject doc = json_report("table3");
    doc.update(JsonObject{{"family", "P(16,16,4)"},
                          {"patterns", o.patterns},
                          {"seed", o.seed},
                          {"method", o.method}});
    doc.update(objective_json(objective));
    doc["rows"] = js;
    out << json_text(doc);
    return;
  }
  out << fmt::format(
      "Laine-Aila Table 3 re-run: P(16,16,4), {} patterns per distribution, seed {}, {}\naapat "
      "(paper)   Min              Avg              Max              Opt W     "
      "       Opt W+P\n",
      o.patterns, o.seed, objective.caption());
  for (const Table3Row& r : rows) {
    out << fmt::format("{:<14}", r.distribution);
    for (int c = 0; c < 5; ++c) out << fmt::format("  {:.3f} ({:.3f})", r.e2[c], r.paper[c]);
    out << "\n";
  }
}

}  // namespace

Action add_table3_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("table3", "re-run Laine-Aila Table 3 (P(16,16,4) distributions)");
  auto o = std::make_shared<Table3Options>();
  cmd->add_option("--patterns", o->patterns, "random patterns per distribution")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000000));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_option("--iterations", o->iterations, "optimizer iterations per stage")
      ->capture_default_str()
      ->check(CLI::Range(1, 10000000));
  cmd->add_option("--method", o->method,
                  "Opt W+P's method: descent (with its minimax polish), or the epigraph form with "
                  "NLopt: slsqp, mma, ccsaq")
      ->capture_default_str()
      ->check(CLI::IsMember({"descent", "minimax", "slsqp", "mma", "ccsaq"}));
  cmd->add_flag("--json", o->json, "print the numbers as JSON");
  o->metric.add_to(cmd, kPapersObjective);
  return [o](std::ostream& out) { run_table3(*o, out); };
}

}  // namespace aapat
