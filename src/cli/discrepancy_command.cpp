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

namespace {

JsonObject discrepancy_json(const std::string& source, const DiscrepancyReport& d) {
  JsonObject doc = json_report("discrepancy");
  doc.update(JsonObject{{"source", source}, {"points", d.points}});
  if (d.l2_star) doc["l2_star"] = *d.l2_star;
  if (d.star)
    doc.update(JsonObject{{"star_lower", d.star->lower},
                          {"star_upper", d.star->upper},
                          {"star_exact", d.star->exact},
                          {"star_gap", d.star->upper - d.star->lower}});
  if (d.edge)
    doc.update(JsonObject{{"edge", d.edge->value}, {"edge_normal_deg", d.edge->normal_deg}});
  return doc;
}

std::string discrepancy_text(const std::string& source, const DiscrepancyReport& d) {
  std::string text = fmt::format("{} ({} points)\n", source, d.points);
  if (d.l2_star) text += fmt::format("  L2-star discrepancy  {:.6f}\n", *d.l2_star);
  if (d.star && d.star->exact)
    text += fmt::format("  star discrepancy     {:.6f} (exact)\n", d.star->upper);
  else if (d.star)
    text += fmt::format("  star discrepancy     in [{:.6f}, {:.6f}] (grid bounds; gap {:.6f})\n",
                        d.star->lower, d.star->upper, d.star->upper - d.star->lower);
  if (d.edge)
    text += fmt::format("  edge discrepancy     {:.6f} (worst half-plane normal at {:g} degrees)\n",
                        d.edge->value, d.edge->normal_deg);
  return text;
}

}  // namespace

Action add_discrepancy_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("discrepancy", "L2-star, star and edge discrepancy of a point set");
  auto src = std::make_shared<PointOptions>();
  auto json = std::make_shared<bool>(false);
  auto measures = std::make_shared<std::string>("l2-star,star,edge");
  src->add_to(cmd);
  cmd->add_option("--measure", *measures, "the discrepancies to compute, a comma list")
      ->capture_default_str();
  cmd->add_flag("--json", *json, "print JSON (the measures computed)");
  return [src, json, measures](std::ostream& out) {
    const DiscrepancyMeasures m = parse_measures(*measures);
    DiscrepancyReport d;
    {
      Progress bar("discrepancy");
      d = discrepancy_report(src->points(), m, bar.callback());
    }
    out << (*json ? json_text(discrepancy_json(src->source, d)) : discrepancy_text(src->source, d));
  };
}

}  // namespace aapat
