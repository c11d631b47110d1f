// `aapat hardware-table`: what the 1/16-pixel lattice of programmable sample
// positions costs. For 2, 4, 8 and 16 samples per pixel: the standard MSAA
// pattern with a box resolve and with optimized weights, the best pattern
// found on the lattice for Direct3D 12 tier 1 (and tier 2 where the count
// allows), each beside the continuous optimum of its family; then the
// 1.25-2 sample sharing schemes snapped to the lattice and searched there.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/progress.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/lattice.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/json_report.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/lattice_search.h"
#include "aapat/optimize/multistart.h"

namespace aapat {
namespace {

struct Figures {
  double continuous = 0, lattice = 0;
  std::string layout;  // "2x2, 2x MSAA, reads 4"
};

std::string layout_text(const Pattern& p, const ApiProfile& profile) {
  const HardwareLayout L = hardware_layout(p, profile);
  return fmt::format("{}x{} grid, {}x MSAA, reads {}", L.grid_w, L.grid_h, L.sample_count,
                     format_cost(L.reads()));
}

// A family searched continuously, then on the lattice from there.
Figures search(const Metric& metric, const std::string& family, const std::string& placement,
               const ApiProfile& profile, int starts, uint64_t seed) {
  const FamilySpec spec = parse_family(family, placement);
  const SeedFunction seeds = family_seeds(spec, SeedKind::kJittered, seed, metric.filter());
  OptimizerSettings settings;
  const MultiStartResult r = multistart(metric, starts, seed, seeds, settings, 0);
  const LatticeSearch lat =
      lattice_search_from(metric, r.best_problem, seeds, starts, seed, kLatticeSteps, settings);
  return {r.starts[r.best].run.final_e2, lat.run.final_e2,
          layout_text(pattern_of(lat.best), profile)};
}

// A pattern snapped, its weights optimized, then searched on the lattice from there.
Figures snapped(const Metric& metric, const Pattern& p, const ApiProfile& profile) {
  Problem problem = problem_from_pattern(snap_to_lattice(p, kLatticeSteps));
  const LatticeRun run = lattice_descent(metric, problem, kLatticeSteps, OptimizerSettings{});
  return {metric.evaluate(p).e2, run.final_e2, layout_text(pattern_of(problem), profile)};
}

}  // namespace

Action add_hardware_table_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "hardware-table", "E2 of standard and optimized patterns on the 1/16 lattice of the APIs");
  struct Options {
    MetricOptions metric;
    int starts = 32;
    uint64_t seed = 1;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  o->metric.add_to(cmd);
  cmd->add_option("--starts", o->starts, "random starts per family")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_flag("--json", o->json, "print the table as JSON (docs/json.md)");
  return [o](std::ostream& out) {
    JsonObject rows = JsonObject::array();
    const Metric metric = o->metric.make();
    const ApiProfile &tier1 = api_profile("d3d12-tier1"), &tier2 = api_profile("d3d12-tier2");
    std::string table =
        "| n | pattern | profile | layout | E2 continuous | E2 on the lattice | lattice cost |\n"
        "| ---: | --- | --- | --- | ---: | ---: | ---: |\n";
    auto row = [&](const std::string& n, const std::string& what, const ApiProfile& profile,
                   const Figures& f) {
      table +=
          fmt::format("| {} | {} | {} | {} | {:.4f} | {:.4f} | {:+.4f} |\n", n, what, profile.name,
                      f.layout, f.continuous, f.lattice, f.lattice - f.continuous);
      rows.push_back({{"n", n},
                      {"pattern", what},
                      {"profile", profile.name},
                      {"layout", f.layout},
                      {"e2_continuous", f.continuous},
                      {"e2_lattice", f.lattice}});
    };
    Progress bar("hardware-table");
    int done = 0;
    const int total = 4 * 3 + 2 + 7;
    for (int n : {2, 4, 8, 16}) {
      const Pattern msaa = catalog_pattern(fmt::format("msaa-{}", n));
      const double box = metric.evaluate(msaa).e2;
      row(std::to_string(n), fmt::format("msaa-{} (standard), box resolve", n), tier1,
          {box, box, layout_text(msaa, tier1)});
      const double w = metric.evaluate(with_optimized_weights(metric, msaa, false)).e2;
      row(std::to_string(n), fmt::format("msaa-{} positions, optimized weights", n), tier1,
          {w, w, layout_text(msaa, tier1)});
      bar.update(done += 2, total, fmt::format("msaa-{}", n));
      // The search's local optima, or the standard pattern polished on the lattice.
      Figures best = search(metric, fmt::format("P(1,1,{})", n), "", tier1, o->starts, o->seed);
      const Figures polished = snapped(metric, msaa, tier1);
      const bool from_standard = polished.lattice < best.lattice;
      if (from_standard) best.lattice = polished.lattice;
      row(std::to_string(n),
          fmt::format(
              "best P(1,1,{}){}", n,
              from_standard ? " (msaa-" + std::to_string(n) + " polished on the lattice)" : ""),
          tier1, best);
      bar.update(++done, total, fmt::format("P(1,1,{})", n));
      if (n <= 4) {
        row(std::to_string(n), fmt::format("best P(4,4,{}) (2x2-pixel kernels)", n), tier2,
            search(metric, fmt::format("P(4,4,{})", n), "", tier2, o->starts, o->seed));
        bar.update(++done, total, fmt::format("P(4,4,{})", n));
      }
    }
    for (const char* name : {"hasselgren-a", "hasselgren-b", "hasselgren-c", "hasselgren-d",
                             "hasselgren-e", "hasselgren-f", "quincunx-hasselgren"}) {
      const Pattern p = catalog_pattern(name);
      const ApiProfile& profile = p.tile_w == 1 ? tier1 : tier2;
      row(format_cost(samples_per_pixel(p)), fmt::format("{} snapped, then searched", name),
          profile, snapped(metric, p, profile));
      bar.update(++done, total, name);
    }
    if (o->json) {
      JsonObject doc = json_report("hardware-table");
      doc.update(JsonObject{{"filter", metric.filter().name()},
                            {"acuity", metric.acuity().name},
                            {"starts", o->starts},
                            {"seed", o->seed},
                            {"rows", rows}});
      out << json_text(doc);
      return;
    }
    out << fmt::format(
        "E2 ({}, acuity {}); continuous: the family's optimum from {} starts (catalog rows: the "
        "pattern as published); lattice: positions on 1/16 pixel, weights optimized\n\n{}",
        metric.filter().name(), metric.acuity().name, o->starts, table);
  };
}

}  // namespace aapat
