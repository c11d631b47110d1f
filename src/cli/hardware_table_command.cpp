// `aapat hardware-table`: what the 1/16-pixel lattice of programmable sample
// positions costs. For 2, 4, 8 and 16 samples per pixel: the standard MSAA
// pattern with a box resolve and with optimized weights, the best pattern
// found on the lattice for Direct3D 12 tier 1 (and tier 2 where the count
// allows), each beside the continuous optimum of its family; then the
// 1.25-2 sample sharing schemes snapped to the lattice and searched there.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/study/study_json.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"

namespace aapat {

Action add_hardware_table_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "hardware-table", "E2 of standard and optimized patterns on the 1/16 lattice of the APIs");
  struct Options {
    MetricOptions metric;
    HardwareTableSettings settings;  // bound to the options, checked by the library
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  o->metric.add_to(cmd);
  cmd->add_option("--starts", o->settings.starts, "random starts per family")
      ->capture_default_str();
  add_seed_option(cmd, o->settings.seed, "random seed");
  cmd->add_flag("--json", o->json, "print the table as JSON (docs/json.md)");
  return [o](std::ostream& out) {
    const Objective objective = o->metric.resolve();
    std::vector<HardwareTableRow> rows;
    {
      Progress bar("hardware-table");
      rows = hardware_table(objective.metric(), o->settings, bar.callback());
    }
    // The document is the result; the Markdown table is printed from it.
    const JsonObject doc = hardware_table_json(objective, o->settings, rows);
    if (o->json) {
      out << json_text(doc);
      return;
    }
    out << fmt::format(
        "E2 under the {}; continuous: the family's optimum from {} starts (catalog rows: the "
        "pattern as published); lattice: positions on 1/16 pixel, weights optimized\n\n",
        objective.caption(), doc["starts"].get<int>());
    out << "| n | pattern | profile | layout | E2 continuous | E2 on the lattice | lattice cost |\n"
           "| ---: | --- | --- | --- | ---: | ---: | ---: |\n";
    for (const JsonObject& r : doc["rows"]) {
      const double continuous = r["e2_continuous"].get<double>(),
                   lattice = r["e2_lattice"].get<double>();
      out << fmt::format("| {} | {} | {} | {} | {:.4f} | {:.4f} | {:+.4f} |\n",
                         r["n"].get<std::string>(), r["pattern"].get<std::string>(),
                         r["profile"].get<std::string>(), r["layout"].get<std::string>(),
                         continuous, lattice, lattice - continuous);
    }
  };
}

}  // namespace aapat
