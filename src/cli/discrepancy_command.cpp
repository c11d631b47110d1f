// `aapat discrepancy`: the L2 discrepancies, star and edge discrepancy of a point set.
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
  for (const L2Value& v : d.l2) doc[std::string(l2_kind_info(v.kind).key)] = v.value;
  if (d.star)
    doc.update(JsonObject{{"star_lower", d.star->lower},
                          {"star_upper", d.star->upper},
                          {"star_exact", d.star->exact},
                          {"star_gap", d.star->upper - d.star->lower}});
  if (d.edge)
    doc.update(JsonObject{{"edge", d.edge->value}, {"edge_normal_deg", d.edge->normal_deg}});
  return doc;
}

// Six significant digits: the discrepancies of large sets are 1e-6 and less.
std::string discrepancy_text(const std::string& source, const DiscrepancyReport& d) {
  std::string text = fmt::format("{} ({} points)\n", source, d.points);
  auto line = [&](const std::string& label, const std::string& value) {
    text += fmt::format("  {:<28}{}\n", label + " discrepancy", value);
  };
  for (const L2Value& v : d.l2)
    line(std::string(l2_kind_info(v.kind).label), fmt::format("{:.6g}", v.value));
  if (d.star && d.star->exact)
    line("star", fmt::format("{:.6g} (exact)", d.star->upper));
  else if (d.star)
    line("star", fmt::format("in [{:.6g}, {:.6g}] (bounds; gap {:.3g})", d.star->lower,
                             d.star->upper, d.star->upper - d.star->lower));
  if (d.edge)
    line("edge", fmt::format("{:.6g} (worst half-plane normal at {:g} degrees)", d.edge->value,
                             d.edge->normal_deg));
  return text;
}

}  // namespace

Action add_discrepancy_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "discrepancy", "L2 (star, centred, ...), star and edge discrepancy of a point set");
  auto src = std::make_shared<PointOptions>();
  auto json = std::make_shared<bool>(false);
  auto measures = std::make_shared<std::string>("l2-star,star,edge");
  src->add_to(cmd);
  cmd->add_option("--measure", *measures,
                  "the discrepancies to compute, a comma list of l2-star, l2-generalized, "
                  "l2-centred, l2-wrap-around, l2-unanchored, l2-symmetric, star, edge, or all")
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
