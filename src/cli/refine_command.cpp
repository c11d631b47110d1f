// `aapat refine PATTERN --objective perceptual[:...]`: the pattern refined
// under the perceptual objective by a derivative-free search
// (study/perceptual_search.h), its value before and after.
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/study/perceptual_search.h"
#include "cli/commands.h"
#include "cli/progress.h"

namespace aapat {

Action add_refine_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "refine", "refine a pattern's positions and weights under the perceptual objective");
  struct Options {
    std::string pattern, objective = std::string(kPerceptualObjective), output, name;
    PerceptualSearchSettings search;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("pattern", o->pattern, "the start: a catalog name or pattern file")->required();
  cmd->add_option("--objective,-O", o->objective,
                  "the perceptual objective's spec, perceptual:key=value,... (aapat list)")
      ->capture_default_str();
  cmd->add_option("--max-tries", o->search.max_tries, "objective evaluations at most")
      ->capture_default_str();
  cmd->add_option("--step", o->search.step, "the first step, pixels")->capture_default_str();
  cmd->add_option("--min-step", o->search.min_step, "the last step, pixels")->capture_default_str();
  cmd->add_option("-o,--output", o->output, "write the refined pattern (.json or .xyw)");
  cmd->add_option("--name", o->name, "the refined pattern's name (default: START-perceptual)");
  cmd->add_flag("--json", o->json, "print JSON");
  return [o](std::ostream& out) {
    if (!o->output.empty() && !is_pattern_path(o->output))
      throw Error(fmt::format("--output: '{}' must end in .json or .xyw", o->output));
    if (!is_perceptual(o->objective))
      throw ParameterError("objective",
                           fmt::format(" '{}': refine searches under the perceptual objective "
                                       "(perceptual:key=value,...); E2's optimizer is `aapat "
                                       "optimize`",
                                       o->objective));
    const PerceptualObjective objective(parse_perceptual(o->objective));
    const Pattern start = resolve_pattern(o->pattern);
    PerceptualSearchResult r;
    {
      Progress bar("refine");
      r = refine_perceptual(start, objective, o->search, bar.callback());
    }
    if (!o->name.empty()) r.pattern.name = o->name;
    if (!o->output.empty()) save_pattern_file(r.pattern, o->output);
    const JsonObject doc = refine_json(objective.spec(), start, r);
    if (o->json) {
      out << json_text(doc);
      return;
    }
    out << fmt::format("objective {}\n{} {}: {:.6f} -> {:.6f} after {} evaluations\n",
                       objective.spec().text(), start.name, family(start), r.start_value, r.value,
                       r.tries);
    if (!o->output.empty()) out << "wrote " << o->output << "\n";
  };
}

}  // namespace aapat
