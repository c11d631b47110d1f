// `aapat discrepancy`: L2-star, star and edge discrepancy of a point set.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/study/point_set_study.h"
#include "cli/commands.h"
#include "cli/point_options.h"
#include "cli/progress.h"

namespace aapat {

Action add_discrepancy_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("discrepancy", "L2-star, star and edge discrepancy of a point set");
  auto src = std::make_shared<PointOptions>();
  auto json = std::make_shared<bool>(false);
  src->add_to(cmd);
  cmd->add_flag("--json", *json, "print JSON");
  return [src, json](std::ostream& out) {
    DiscrepancyReport d;
    {
      Progress bar("discrepancy");
      d = discrepancy_report(src->points(), bar.callback());
    }
    if (*json) {
      JsonObject doc = json_report("discrepancy");
      doc.update(JsonObject{{"source", src->source},
                            {"points", d.points},
                            {"l2_star", d.l2_star},
                            {"star_lower", d.star.lower},
                            {"star_upper", d.star.upper},
                            {"star_exact", d.star.exact},
                            {"edge", d.edge.value},
                            {"edge_normal_deg", d.edge.normal_deg}});
      out << json_text(doc);
      return;
    }
    out << fmt::format("{} ({} points)\n  L2-star discrepancy  {:.6f}\n", src->source, d.points,
                       d.l2_star);
    if (d.star.exact)
      out << fmt::format("  star discrepancy     {:.6f} (exact)\n", d.star.upper);
    else
      out << fmt::format("  star discrepancy     in [{:.6f}, {:.6f}] (grid bounds)\n", d.star.lower,
                         d.star.upper);
    out << fmt::format("  edge discrepancy     {:.6f} (worst half-plane normal at {:g} degrees)\n",
                       d.edge.value, d.edge.normal_deg);
  };
}

}  // namespace aapat
