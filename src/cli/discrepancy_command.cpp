// `aapat discrepancy`: the L2 discrepancies, star and edge discrepancy of a point set.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/study/study_json.h"
#include "cli/commands.h"
#include "cli/point_options.h"
#include "cli/progress.h"

namespace aapat {

namespace {

// Printed from the document. Six significant digits: the discrepancies of
// large sets are 1e-6 and less.
std::string discrepancy_text(const JsonObject& doc) {
  std::string text = fmt::format("{} ({} points)\n", doc["source"].get<std::string>(),
                                 doc["points"].get<size_t>());
  auto line = [&](const std::string& label, const std::string& value) {
    text += fmt::format("  {:<28}{}\n", label + " discrepancy", value);
  };
  auto value = [&](const char* key) { return doc[key].get<double>(); };
  for (const L2KindInfo& kind : l2_kinds())
    if (const std::string key(kind.key); doc.contains(key))
      line(std::string(kind.label), fmt::format("{:.6g}", value(key.c_str())));
  if (doc.contains("star_is_exact") && doc["star_is_exact"].get<bool>())
    line("star", fmt::format("{:.6g} (exact)", value("star_exact")));
  else if (doc.contains("star_is_exact"))
    line("star", fmt::format("in [{:.6g}, {:.6g}] (bounds; gap {:.3g})", value("star_lower"),
                             value("star_upper"), value("star_gap")));
  if (doc.contains("edge"))
    line("edge", fmt::format("{:.6g} (worst half-plane normal at {:g} degrees)", value("edge"),
                             value("edge_normal_deg")));
  return text;
}

}  // namespace

Action add_discrepancy_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "discrepancy", "L2 (star, centred, ...), star and edge discrepancy of a point set");
  auto src = std::make_shared<PointOptions>();
  auto json = std::make_shared<bool>(false);
  auto measures = std::make_shared<std::string>(kDefaultDiscrepancyMeasures);
  src->add_to(cmd);
  std::string kinds;
  for (const L2KindInfo& k : l2_kinds()) kinds += std::string(k.name) + ", ";
  cmd->add_option("--measure", *measures,
                  "the discrepancies to compute, a comma list of " + kinds +
                      "star, edge, or all (each reported as D, not D^2)")
      ->capture_default_str();
  cmd->add_flag("--json", *json, "print JSON (the measures computed)");
  return [src, json, measures](std::ostream& out) {
    const DiscrepancyMeasures m = parse_measures(*measures);
    DiscrepancyReport d;
    {
      Progress bar("discrepancy");
      d = discrepancy_report(src->points(), m, bar.callback());
    }
    const JsonObject doc = discrepancy_json(src->source, d);
    out << (*json ? json_text(doc) : discrepancy_text(doc));
  };
}

}  // namespace aapat
