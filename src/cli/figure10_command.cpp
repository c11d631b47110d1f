// `aapat figure10`: Laine-Aila Figure 10 re-run. The best E2 found against
// samples per pixel for P(1,1,n), P(4,1+,n), P(1,4,n) and P(4,4,n), n = 2..6,
// and P(4,1+,n) for n = 1.25..2 in steps of 1/4. For P(4,1+,n) the placement
// matters: each n tries the placements listed below and keeps the best.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"
#include "aapat/io/json_report.h"
#include "aapat/io/line_plot.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/multistart.h"

namespace aapat {
namespace {

// Placements tried for the mirrored family: the structures of Hasselgren's
// schemes A-F below n = 2, FLIPQUAD's edges plus inside samples above.
std::vector<std::string> mirrored_placements(double n) {
  if (n == 1.25) return {"top-left,bottom,right"};
  if (n == 1.5) return {"left,bottom,top", "left,bottom-left,top,bottom-right"};
  if (n == 1.75) return {"bottom-left,inside,right", "bottom-left,left,top,right"};
  if (n == 2)
    return {"left,right,bottom,top", "inside,bottom-left,bottom-right,top-left,top-right"};
  std::string edges = "left,right,bottom,top", inside;
  for (int i = 0; i < n - 2; ++i) edges += ",inside";
  for (int i = 0; i < n; ++i) inside += i ? ",inside" : "inside";
  return {edges, inside};
}

}  // namespace

Action add_figure10_command(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("figure10", "re-run Laine-Aila Figure 10: best E2 per family and n");
  struct Options {
    int starts = 32;
    uint64_t seed = 1;
    std::string csv, svg;
    bool json = false;
    MetricOptions metric;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--starts", o->starts, "random starts per family, n and placement")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_option("--csv", o->csv, "write family, n, placement, E2 as CSV");
  cmd->add_option("--svg", o->svg, "write the plot");
  cmd->add_flag("--json", o->json, "print the points as JSON (docs/json.md)");
  o->metric.add_to(cmd);
  return [o](std::ostream& out) {
    const Metric metric = o->metric.make();
    struct Point {
      std::string family, placement;
      double n, e2;
    };
    std::vector<Point> points;
    std::vector<LineSeries> lines;
    const std::vector<std::string> families = {"P(1,1,{})", "P(4,1+,{})", "P(1,4,{})", "P(4,4,{})"};
    int total = 0, done = 0;
    for (const auto& f : families) total += f == "P(4,1+,{})" ? 9 : 5;
    Progress bar("figure10");
    for (const auto& f : families) {
      LineSeries line{fmt::vformat(f, fmt::make_format_args("n")), {}, {}};
      std::vector<double> ns = {2, 3, 4, 5, 6};
      if (f == "P(4,1+,{})") ns.insert(ns.begin(), {1.25, 1.5, 1.75});
      for (double n : ns) {
        const std::string fam = fmt::vformat(f, fmt::make_format_args(format_cost(n)));
        Point best{fam, "", n, INFINITY};
        const std::vector<std::string> placements =
            f == "P(4,1+,{})" ? mirrored_placements(n) : std::vector<std::string>{""};
        for (const auto& placement : placements) {
          const FamilySpec spec = parse_family(fam, placement);
          const MultiStartResult r =
              multistart(metric, o->starts, o->seed,
                         family_seeds(spec, SeedKind::kJittered, o->seed, metric.filter()),
                         OptimizerSettings{}, 0);
          const double e2 = r.starts[r.best].run.final_e2;
          if (e2 < best.e2) best = {fam, placement, n, e2};
        }
        points.push_back(best);
        line.x.push_back(n);
        line.y.push_back(best.e2);
        bar.update(++done, total, fmt::format("{} {:.4f}", fam, best.e2));
      }
      lines.push_back(line);
    }
    std::ostream discard(nullptr);
    std::ostream& text = o->json ? discard : out;
    text << fmt::format(
        "Laine-Aila Figure 10 re-run: best E2 of {} jittered starts, seed {}, filter {}\n",
        o->starts, o->seed, metric.filter().name());
    text << fmt::format("{:<14} {:>5} {:>8}  {}\n", "family", "n", "E2", "placement");
    std::string csv = "family,n,e2,placement\n";
    JsonObject rows = JsonObject::array();
    for (const auto& p : points) {
      rows.push_back({{"family", p.family}, {"n", p.n}, {"e2", p.e2}, {"placement", p.placement}});
      text << fmt::format("{:<14} {:>5} {:>8.4f}  {}\n", p.family, format_cost(p.n), p.e2,
                          p.placement.empty() ? "all inside" : p.placement);
      csv += fmt::format("{},{},{:.6f},\"{}\"\n", p.family, format_cost(p.n), p.e2, p.placement);
    }
    if (!o->csv.empty()) write_output(o->csv, csv, out);
    if (o->json) {
      JsonObject doc = json_report("figure10");
      doc.update(JsonObject{{"starts", o->starts},
                            {"seed", o->seed},
                            {"filter", metric.filter().name()},
                            {"acuity", metric.acuity().name},
                            {"rows", rows}});
      out << json_text(doc);
    }
    if (!o->svg.empty())
      write_output(o->svg,
                   line_plot_svg({"Best E2 against samples per pixel (Laine-Aila Fig. 10 re-run)",
                                  "samples per pixel n",
                                  "E2",
                                  {1, 2, 3, 4, 5, 6},
                                  1,
                                  6,
                                  true},
                                 lines),
                   out);
  };
}

}  // namespace aapat
