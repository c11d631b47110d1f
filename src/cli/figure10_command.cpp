// `aapat figure10`: Laine-Aila Figure 10 re-run. The best E2 found against
// samples per pixel for P(1,1,n), P(4,1+,n), P(1,4,n) and P(4,4,n), n = 2..6,
// and P(4,1+,n) for n = 1.25..2 in steps of 1/4. For P(4,1+,n) the placement
// matters: each n tries the placements listed below and keeps the best.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/io/line_plot.h"
#include "aapat/study/paper_tables.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"

namespace aapat {

namespace {

struct Figure10Options {
  int starts = 32;
  uint64_t seed = 1;
  std::string csv, svg;
  bool json = false;
  MetricOptions metric;
};

void run_figure10(Figure10Options& o, std::ostream& out) {
  const Objective objective = o.metric.resolve();
  const Metric metric = objective.metric();
  Figure10 fig;
  {
    Progress bar("figure10");
    fig = figure10(metric, {o.starts, o.seed}, bar.callback());
  }
  std::ostream discard(nullptr);
  std::ostream& text = o.json ? discard : out;
  text << fmt::format("Laine-Aila Figure 10 re-run: best E2 of {} jittered starts, seed {}, {}\n",
                      o.starts, o.seed, objective.caption());
  text << fmt::format("{:<14} {:>5} {:>8}  {}\n", "family", "n", "E2", "placement");
  std::string csv = "family,n,e2,placement,objective\n";
  JsonObject rows = JsonObject::array();
  std::vector<LineSeries> lines;
  for (const auto& series : fig.series) lines.push_back({series, {}, {}});
  for (const auto& p : fig.points) {
    rows.push_back({{"family", p.family}, {"n", p.n}, {"e2", p.e2}, {"placement", p.placement}});
    text << fmt::format("{:<14} {:>5} {:>8.4f}  {}\n", p.family, format_cost(p.n), p.e2,
                        p.placement.empty() ? "all inside" : p.placement);
    csv += fmt::format("{},{},{:.6f},\"{}\",\"{}\"\n", p.family, format_cost(p.n), p.e2,
                       p.placement, objective.text());
    LineSeries& line = lines[p.series];
    line.x.push_back(p.n);
    line.y.push_back(p.e2);
  }
  if (!o.csv.empty()) write_output(o.csv, csv, out);
  if (o.json) {
    JsonObject doc = json_report("figure10");
    doc.update(JsonObject{{"starts", o.starts}, {"seed", o.seed}});
    doc.update(objective_json(objective));
    doc["rows"] = rows;
    out << json_text(doc);
  }
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
  cmd->add_option("--starts", o->starts, "random starts per family, n and placement")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_option("--csv", o->csv, "write family, n, placement, E2 as CSV");
  cmd->add_option("--svg", o->svg, "write the plot");
  cmd->add_flag("--json", o->json, "print the points as JSON (docs/json.md)");
  o->metric.add_to(cmd, kPapersObjective);
  return [o](std::ostream& out) { run_figure10(*o, out); };
}

}  // namespace aapat
