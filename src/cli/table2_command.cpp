// `aapat table2`: Hasselgren Table 2's E2, RMSE and max-deviation columns
// re-measured on the translating circle, the paper's numbers beside.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/io/json_report.h"
#include "aapat/study/pattern_studies.h"
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
    if (o->json) {
      JsonObject js = JsonObject::array();
      for (const Table2Row& r : rows)
        js.push_back({{"pattern", r.pattern},
                      {"label", r.label},
                      {"e2", r.e2},
                      {"rmse", r.rmse},
                      {"max_deviation", r.max_deviation},
                      {"paper",
                       {{"e2", r.paper_e2},
                        {"rmse", r.paper_rmse},
                        {"max_deviation", r.paper_max_deviation}}}});
      JsonObject doc = json_report("table2");
      doc.update(JsonObject{{"animation", "circle"},
                            {"frames", a.frames},
                            {"width", a.width},
                            {"height", a.height},
                            {"reference", describe_reference(a.reference)}});
      doc.update(objective_json(named_objective(kPapersObjective)));
      doc["rows"] = js;
      out << json_text(doc);
      return;
    }
    out << fmt::format(
        "Hasselgren Table 2 re-measured: translating circle, {} frames of {}x{}, reference {} "
        "jittered samples per pixel with {}; E2 under the {}\naapat (paper)         E2             "
        "  "
        "RMSE              max dev.\n",
        a.frames, a.width, a.height, a.reference.samples, make_filter(a.reference.filter).name(),
        named_objective(kPapersObjective).caption());
    for (const Table2Row& r : rows)
      out << fmt::format("{:<21} {:>6.3f} ({:.3f})  {:>6.3f} ({:.3f})  {:>4} ({})\n", r.label, r.e2,
                         r.paper_e2, r.rmse, r.paper_rmse, r.max_deviation, r.paper_max_deviation);
  };
}

}  // namespace aapat
