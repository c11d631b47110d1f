// `aapat table3`: Laine-Aila Table 3 re-run. P(16,16,4) patterns (4x4 pixel
// tiles, 4x4 pixel kernels, 64 samples per kernel) drawn as jittered grids and
// Poisson-disk sets with Mitchell-Netravali weights h(x) h(y): min / avg / max
// E2 over many patterns, then the best optimized for weights only (Opt W) and
// from there for weights and positions (Opt W+P).
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/study/optimize_run.h"
#include "aapat/study/study_json.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"

namespace aapat {

namespace {

// The options bind to the library's settings (and their defaults); the
// library checks them.
struct Table3Options {
  Table3Settings settings;
  std::string method = method_key(Table3Settings{}.method);
  bool json = false;
  MetricOptions metric;
};

void run_table3(Table3Options& o, std::ostream& out) {
  const Objective objective = o.metric.resolve();
  o.settings.method = parse_method(o.method);
  std::vector<Table3Row> rows;
  {
    Progress bar("table3");
    rows = table3(objective.metric(), o.settings, bar.callback());
  }
  // The document is the result; the text table is printed from it.
  const JsonObject doc = table3_json(objective, o.settings, rows);
  if (o.json) {
    out << json_text(doc);
    return;
  }
  out << fmt::format(
      "Laine-Aila Table 3 re-run: {}, {} patterns per distribution, seed {}, {}\naapat "
      "(paper)   Min              Avg              Max              Opt W     "
      "       Opt W+P\n",
      doc["family"].get<std::string>(), doc["patterns"].get<int>(), doc["seed"].get<uint64_t>(),
      objective.caption());
  for (const JsonObject& r : doc["rows"]) {
    out << fmt::format("{:<14}", r["distribution"].get<std::string>());
    int c = 0;
    for (const char* key : {"min", "avg", "max", "opt_w", "opt_wp"})
      out << fmt::format("  {:.3f} ({:.3f})", r[key].get<double>(), r["paper"][c++].get<double>());
    out << "\n";
  }
}

}  // namespace

Action add_table3_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("table3", "re-run Laine-Aila Table 3 (P(16,16,4) distributions)");
  auto o = std::make_shared<Table3Options>();
  cmd->add_option("--patterns", o->settings.patterns, "random patterns per distribution")
      ->capture_default_str();
  add_seed_option(cmd, o->settings.seed, "random seed");
  cmd->add_option("--iterations", o->settings.iterations, "optimizer iterations per stage")
      ->capture_default_str();
  cmd->add_option("--method", o->method, "Opt W+P's method: " + method_help())
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "print the numbers as JSON");
  o->metric.add_to(cmd, kPapersObjective);
  return [o](std::ostream& out) { run_table3(*o, out); };
}

}  // namespace aapat
