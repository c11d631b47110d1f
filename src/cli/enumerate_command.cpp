// `aapat enumerate`: every placement configuration of the mirrored P(4,1+,n)
// family for the given costs (Hasselgren et al. Sec. 5), optionally optimized
// and ranked by E2 within each cost.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/text.h"
#include "aapat/generate/enumerate.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/pattern_svg.h"
#include "aapat/study/study_json.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"

namespace aapat {
namespace {

std::string counts_text(const Enumeration& e, const EnumerationSettings& s) {
  std::string text = fmt::format(
      "P(4,1+,n) placement configurations (rotations and reflections removed; at "
      "most {} samples per edge{})\n",
      s.rules.max_per_edge, s.rules.cull_one_edge ? "; one-border-line configurations culled" : "");
  for (double n : s.costs) text += fmt::format("  n = {:<5} {:>4}\n", format_cost(n), e.count(n));
  return text + fmt::format("  total     {:>4}\n", e.rows.size());
}

// The table and the CSV are printed from the document's rows.
std::string rows_text(const JsonObject& doc, const Objective& objective) {
  const bool optimized = doc["optimized"].get<bool>();
  std::string text = optimized ? objective.caption() + "\n" : "";
  text += fmt::format("{:>4} {:>5} {:>5} {:>8}  {}\n", "id", "n", "reads", "E2", "placement");
  for (const JsonObject& r : doc["rows"])
    text += fmt::format("{:>4} {:>5} {:>5} {:>8}  {}\n", r["id"].get<int>(),
                        format_cost(r["n"].get<double>()), r["samples_read"].get<int>(),
                        optimized ? fmt::format("{:.4f}", r["e2"].get<double>()) : "-",
                        r["placement"].get<std::string>());
  return text;
}

std::string rows_csv(const JsonObject& doc, const Objective& objective) {
  const bool optimized = doc["optimized"].get<bool>();
  std::string csv = "id,n,placement,samples_read,e2,objective\n";
  for (const JsonObject& r : doc["rows"])
    csv += fmt::format("{},{},\"{}\",{},{},\"{}\"\n", r["id"].get<int>(),
                       format_cost(r["n"].get<double>()), r["placement"].get<std::string>(),
                       r["samples_read"].get<int>(),
                       optimized ? fmt::format("{:.6f}", r["e2"].get<double>()) : "",
                       optimized ? objective.text() : "");
  return csv;
}

std::string gallery(const Enumeration& e, const std::vector<double>& costs, int top,
                    const Objective& objective) {
  std::vector<GalleryItem> items;
  for (double n : costs) {
    int shown = 0;
    for (const EnumerationRow& r : e.rows)
      if (r.n == n && shown++ < top)
        items.push_back({r.best, fmt::format("n = {}  E2 {:.4f}", format_cost(n), r.e2),
                         fmt::format("#{}: {} samples read", r.id, r.config.samples())});
  }
  return gallery_svg(items, top,
                     "Best P(4,1+,n) configurations per cost, E2 under the objective " +
                         objective.text() + "; disc area = weight");
}

std::string join_costs(const std::vector<double>& costs) {
  std::string text;
  for (double n : costs) text += (text.empty() ? "" : ",") + format_cost(n);
  return text;
}

// The options bind to the library's settings (and their defaults); the
// library checks them.
struct EnumerateOptions {
  EnumerationSettings settings;
  std::string costs = join_costs(EnumerationSettings{}.costs);
  int top = 3;
  std::string csv, gallery, best_dir;
  bool json = false;
  MetricOptions metric;
};

void run_enumerate(EnumerateOptions& o, std::ostream& out) {
  // With --json the document alone goes to stdout; the text goes nowhere.
  std::ostream discard(nullptr);
  std::ostream& text = o.json ? discard : out;
  const Objective objective = o.metric.resolve();  // a bad --objective or --filter fails first
  const Metric metric = objective.metric();
  EnumerationSettings s = o.settings;
  s.costs.clear();
  for (std::string_view c : split(o.costs)) s.costs.push_back(parse_number(c, "--cost"));
  if ((o.gallery.size() || o.best_dir.size()) && !s.optimize)
    throw Error("--gallery and --best-dir show optimized patterns: add --optimize");
  if (!o.best_dir.empty()) check_directory_target(o.best_dir, "--best-dir");
  const bool optimize = s.optimize;
  s.optimize = false;  // the counts first, so that they show before the long part
  Enumeration e = enumerate_study(metric, s);
  text << counts_text(e, s);
  if (!optimize && o.csv.empty() && !o.json) return;
  if (optimize) {
    Progress bar("enumerate");
    s.optimize = true;
    e = enumerate_study(metric, s, bar.callback());
  }
  const JsonObject doc = enumeration_json(objective, s, e);
  text << rows_text(doc, objective);
  if (!o.csv.empty()) write_output(o.csv, rows_csv(doc, objective), out);
  if (o.json) out << json_text(doc);
  if (!o.gallery.empty()) write_output(o.gallery, gallery(e, s.costs, o.top, objective), out);
  if (!o.best_dir.empty()) {
    ensure_directory(o.best_dir, "--best-dir");
    for (double n : s.costs)
      if (const EnumerationRow* best = e.best(n))
        save_pattern_file(best->best,
                          fmt::format("{}/best-P4-1+-{}.json", o.best_dir, format_cost(n)));
  }
}

}  // namespace

Action add_enumerate_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("enumerate",
                                 "list, optimize and rank every P(4,1+,n) placement configuration");
  auto o = std::make_shared<EnumerateOptions>();
  cmd->add_option("--cost", o->costs, "comma list of costs n, multiples of 1/4")
      ->capture_default_str();
  cmd->add_option("--max-per-edge", o->settings.rules.max_per_edge,
                  "samples one edge may hold (8: as many as the cost allows)")
      ->capture_default_str();
  cmd->add_flag("--cull-one-edge", o->settings.rules.cull_one_edge,
                "drop configurations with every sample on one border line (the paper's hand cull)");
  cmd->add_flag("--optimize", o->settings.optimize, "optimize every configuration and rank by E2");
  cmd->add_option("--starts", o->settings.starts, "random starts per configuration")
      ->capture_default_str();
  add_seed_option(cmd, o->settings.seed, "random seed");
  cmd->add_option("--csv", o->csv, "write the table as CSV");
  cmd->add_flag("--json", o->json, "print the table as JSON (docs/json.md)");
  cmd->add_option("--gallery", o->gallery, "write an SVG of the best configurations of each n");
  cmd->add_option("--top", o->top, "configurations per n in the gallery")->capture_default_str();
  cmd->add_option("--best-dir", o->best_dir, "write the best pattern of each n into this folder");
  o->metric.add_to(cmd);

  return [o](std::ostream& out) { run_enumerate(*o, out); };
}

}  // namespace aapat
