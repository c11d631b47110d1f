// `aapat figure10`: Laine-Aila Figure 10 re-run. The best E2 found against
// samples per pixel for P(1,1,n), P(4,1+,n), P(1,4,n) and P(4,4,n), n = 2..6,
// and P(4,1+,n) for n = 1.25..2 in steps of 1/4. For P(4,1+,n) the placement
// matters: each n tries the placements listed below and keeps the best.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/io/line_plot.h"
#include "aapat/study/study_json.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"

namespace aapat {

namespace {

struct Figure10Options {
  Figure10Settings settings;  // bound to the options, checked by the library
  std::string csv, svg;
  bool json = false;
  MetricOptions metric;
};

void run_figure10(Figure10Options& o, std::ostream& out) {
  const Objective objective = o.metric.resolve();
  Figure10 fig;
  {
    Progress bar("figure10");
    fig = figure10(objective.metric(), o.settings, bar.callback());
  }
  // The document is the result; the text, the CSV and the plot are drawn from it.
  const JsonObject doc = figure10_json(objective, o.settings, fig);
  std::string text = fmt::format(
      "Laine-Aila Figure 10 re-run: best E2 of {} jittered starts, seed {}, {}\n{:<14} {:>5} "
      "{:>8}  {}\n",
      doc["starts"].get<int>(), doc["seed"].get<uint64_t>(), objective.caption(), "family", "n",
      "E2", "placement");
  std::string csv = "family,n,e2,placement,objective\n";
  std::vector<LineSeries> lines;
  for (const JsonObject& p : doc["rows"]) {
    const auto family = p["family"].get<std::string>(), series = p["series"].get<std::string>();
    const auto placement = p["placement"].get<std::string>();
    const double n = p["n"].get<double>(), e2 = p["e2"].get<double>();
    text += fmt::format("{:<14} {:>5} {:>8.4f}  {}\n", family, format_cost(n), e2,
                        placement.empty() ? "all inside" : placement);
    csv += fmt::format("{},{},{:.6f},\"{}\",\"{}\"\n", family, format_cost(n), e2, placement,
                       objective.text());
    if (lines.empty() || lines.back().label != series) lines.push_back({series, {}, {}});
    lines.back().x.push_back(n);
    lines.back().y.push_back(e2);
  }
  if (!o.json) out << text;
  if (!o.csv.empty()) write_output(o.csv, csv, out);
  if (o.json) out << json_text(doc);
  if (!o.svg.empty())
    write_output(
        o.svg,
        line_plot_svg({"Best E2 against samples per pixel (Laine-Aila Fig. 10 re-run), objective " +
                           objective.text(),
                       "samples per pixel n",
                       "E2",
                       {1, 2, 3, 4, 5, 6},
                       1,
                       6,
                       true},
                      lines),
        out);
}

}  // namespace

Action add_figure10_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("figure10", "re-run Laine-Aila Figure 10: best E2 per family and n");
  auto o = std::make_shared<Figure10Options>();
  cmd->add_option("--starts", o->settings.starts, "random starts per family, n and placement")
      ->capture_default_str();
  add_seed_option(cmd, o->settings.seed, "random seed");
  cmd->add_option("--csv", o->csv, "write family, n, placement, E2 as CSV");
  cmd->add_option("--svg", o->svg, "write the plot");
  cmd->add_flag("--json", o->json, "print the points as JSON (docs/json.md)");
  o->metric.add_to(cmd, kPapersObjective);
  return [o](std::ostream& out) { run_figure10(*o, out); };
}

}  // namespace aapat
