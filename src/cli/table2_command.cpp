// `aapat table2`: Hasselgren Table 2's E2, RMSE and max-deviation columns
// re-measured on the translating circle, the paper's numbers beside.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/study/study_json.h"
#include "cli/animation_options.h"
#include "cli/commands.h"
#include "cli/progress.h"

namespace aapat {

Action add_table2_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "table2",
      "re-measure Hasselgren Table 2 (E2, RMSE, max deviation) on the translating circle");
  struct Options : AnimationOptions {
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  add_animation_options(cmd, *o);
  cmd->add_flag("--json", o->json, "print the table as JSON (docs/json.md)");
  return [o](std::ostream& out) {
    const AnimationSettings a = o->settings();
    std::vector<Table2Row> rows;
    {
      Progress bar("table2");
      rows = table2(a, o->reference.source(), bar.callback());
    }
    // The document is the result; the text table is printed from it.
    const JsonObject doc = table2_json(a, rows);
    if (o->json) {
      out << json_text(doc);
      return;
    }
    out << fmt::format(
        "Hasselgren Table 2 re-measured: translating circle, {} frames of {}x{}, reference {} "
        "jittered samples per pixel with {}; E2 under the {}\naapat (paper)         E2          "
        "     RMSE              max dev.\n",
        a.frames, a.width, a.height, a.reference.samples, make_filter(a.reference.filter).name(),
        named_objective(kPapersObjective).caption());
    for (const JsonObject& r : doc["rows"]) {
      const JsonObject& paper = r["paper"];
      out << fmt::format("{:<21} {:>6.3f} ({:.3f})  {:>6.3f} ({:.3f})  {:>4} ({})\n",
                         r["label"].get<std::string>(), r["e2"].get<double>(),
                         paper["e2"].get<double>(), r["rmse"].get<double>(),
                         paper["rmse"].get<double>(), r["max_deviation"].get<int>(),
                         paper["max_deviation"].get<int>());
    }
  };
}

}  // namespace aapat
