// `aapat hardware-table`: what the 1/16-pixel lattice of programmable sample
// positions costs. For 2, 4, 8 and 16 samples per pixel: the standard MSAA
// pattern with a box resolve and with optimized weights, the best pattern
// found on the lattice for Direct3D 12 tier 1 (and tier 2 where the count
// allows), each beside the continuous optimum of its family; then the
// 1.25-2 sample sharing schemes snapped to the lattice and searched there.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/study/paper_tables.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"

namespace aapat {

Action add_hardware_table_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "hardware-table", "E2 of standard and optimized patterns on the 1/16 lattice of the APIs");
  struct Options {
    MetricOptions metric;
    int starts = 32;
    uint64_t seed = 1;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  o->metric.add_to(cmd);
  cmd->add_option("--starts", o->starts, "random starts per family")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_flag("--json", o->json, "print the table as JSON (docs/json.md)");
  return [o](std::ostream& out) {
    const Objective objective = o->metric.resolve();
    const Metric metric = objective.metric();
    std::vector<HardwareTableRow> rows;
    {
      Progress bar("hardware-table");
      rows = hardware_table(metric, {o->starts, o->seed}, bar.callback());
    }
    if (o->json) {
      JsonObject js = JsonObject::array();
      for (const HardwareTableRow& r : rows)
        js.push_back({{"n", r.n},
                      {"pattern", r.pattern},
                      {"profile", r.profile},
                      {"layout", r.layout},
                      {"e2_continuous", r.continuous_e2},
                      {"e2_lattice", r.lattice_e2}});
      JsonObject doc = json_report("hardware-table");
      doc.update(objective_json(objective));
      doc.update(JsonObject{{"starts", o->starts}, {"seed", o->seed}, {"rows", js}});
      out << json_text(doc);
      return;
    }
    out << fmt::format(
        "E2 under the {}; continuous: the family's optimum from {} starts (catalog rows: the "
        "pattern as published); lattice: positions on 1/16 pixel, weights optimized\n\n",
        objective.caption(), o->starts);
    out << "| n | pattern | profile | layout | E2 continuous | E2 on the lattice | lattice cost |\n"
           "| ---: | --- | --- | --- | ---: | ---: | ---: |\n";
    for (const HardwareTableRow& r : rows)
      out << fmt::format("| {} | {} | {} | {} | {:.4f} | {:.4f} | {:+.4f} |\n", r.n, r.pattern,
                         r.profile, r.layout, r.continuous_e2, r.lattice_e2,
                         r.lattice_e2 - r.continuous_e2);
  };
}

}  // namespace aapat
