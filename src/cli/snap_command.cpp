// `aapat snap`: every sample to the nearest lattice point of programmable
// sample positions (1/16 pixel), E2 before and after, optionally with the
// weights re-optimized.
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <tuple>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/lattice.h"
#include "aapat/io/api_export.h"
#include "aapat/io/atomic_file.h"
#include "aapat/io/pattern_json.h"
#include "aapat/study/study_json.h"
#include "cli/commands.h"
#include "cli/metric_options.h"

namespace aapat {

Action add_snap_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "snap", "move every sample to the nearest 1/16-pixel lattice point; E2 before and after");
  struct Options {
    std::string pattern, output;
    MetricOptions metric;
    int lattice = kLatticeSteps;
    bool weights = false, nonnegative = false, json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("pattern", o->pattern, "catalog name or pattern file")->required();
  cmd->add_option("--lattice", o->lattice, "steps per pixel")
      ->capture_default_str()
      ->check(CLI::Range(kMinLatticeSteps, kMaxLatticeSteps));
  o->metric.add_to(cmd);
  cmd->add_flag("--optimize-weights", o->weights,
                "then optimize the weights for the snapped positions");
  cmd->add_flag("--nonnegative", o->nonnegative, "with --optimize-weights: weights >= 0");
  cmd->add_option("-o,--output", o->output, "write the snapped pattern (.json)");
  cmd->add_flag("--json", o->json, "print JSON");
  return [o](std::ostream& out) {
    if (!o->output.empty() && !is_pattern_path(o->output))
      throw Error(fmt::format("--output: '{}' must end in .json or .xyw", o->output));
    if (o->nonnegative && !o->weights)
      throw Error("--nonnegative constrains the weights --optimize-weights finds: add it");
    const Objective objective = o->metric.resolve();
    const Pattern before = resolve_pattern(o->pattern);
    const SnapResult r =
        snap_study(objective.metric(), before, o->lattice, o->weights, o->nonnegative);
    const Pattern& after = r.snapped;
    if (!o->output.empty()) save_pattern_file(after, o->output);
    // The document is the result; the text is printed from it.
    const JsonObject doc = snap_json(objective, before.name, o->lattice, r);
    if (o->json) {
      out << json_text(doc);
      return;
    }
    const double e2_before = doc["e2_before"].get<double>(),
                 e2_snapped = doc["e2_snapped"].get<double>();
    out << objective.caption() << "\n";
    out << fmt::format(
        "{} on the 1/{} lattice ({}): E2 {:.4f} -> {:.4f} ({:+.4f}); largest move "
        "{:.4f} pixel\n",
        doc["pattern"].get<std::string>(), o->lattice, doc["family"].get<std::string>(), e2_before,
        e2_snapped, e2_snapped - e2_before, doc["largest_move"].get<double>());
    if (doc.contains("e2_optimized_weights"))
      out << fmt::format("with weights optimized for the snapped positions: E2 {:.4f}\n",
                         doc["e2_optimized_weights"].get<double>());
    for (size_t k = 0; k < after.sets.size(); ++k)
      for (const Vec2& s : after.sets[k])
        out << fmt::format("  set {}: ({:>2}/{}, {:>2}/{})  {}\n", k, std::lround(s.x * o->lattice),
                           o->lattice, std::lround(s.y * o->lattice), o->lattice, site_name(s));
    if (!o->output.empty()) out << "wrote " << o->output << "\n";
  };
}

}  // namespace aapat
