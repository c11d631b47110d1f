// `aapat refine PATTERN`: the pattern refined by a derivative-free search
// (study/refine_search.h) under the perceptual objective (--objective), or
// under the mean rendered FLIP over scenes (--scenes: content instead of
// charts, as `aapat study --compare` renders it), free or on an API's
// lattice (--api); its value before and after.
#include <fmt/format.h>

#include <memory>
#include <optional>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/study/objective_study.h"
#include "aapat/study/refine_search.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/reference_options.h"

namespace aapat {

Action add_refine_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "refine",
      "refine a pattern's positions and weights under the perceptual objective or rendered FLIP");
  struct Options {
    std::string pattern, objective = std::string(kPerceptualObjective), output, name,
                         size = std::to_string(kRenderedObjectiveSize),
                         measure = kRenderedObjectiveMeasure;
    std::vector<std::string> scenes;
    RefineSettings search;
    ReferenceOptions reference;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("pattern", o->pattern, "the start: a catalog name or pattern file")->required();
  auto* objective =
      cmd->add_option("--objective,-O", o->objective,
                      "the perceptual objective's spec, perceptual:key=value,... (aapat list)")
          ->capture_default_str();
  auto* scenes = cmd->add_option(
      "--scenes", o->scenes,
      "instead: the mean rendered measure over these scenes (as aapat study --compare)");
  scenes->excludes(objective);
  cmd->add_option("--size", o->size, "with --scenes: WIDTHxHEIGHT, or N for N x N")
      ->capture_default_str();
  cmd->add_option("--measure", o->measure,
                  "with --scenes: the rendered measure (flip, rmse, max_deviation, "
                  "one_minus_ssim, tail_rms)")
      ->capture_default_str();
  cmd->add_option("--api", o->search.api,
                  "keep the samples on this API's 1/16-pixel lattice (aapat list)");
  cmd->add_option("--max-tries", o->search.max_tries, "objective evaluations at most")
      ->capture_default_str();
  auto* weight_steps =
      cmd->add_option("--weight-steps", o->search.weight_steps,
                      "then at most this many gradient steps on the weights (the perceptual "
                      "objective's weight gradient; 0: none)")
          ->capture_default_str();
  weight_steps->excludes(scenes);
  cmd->add_option("--step", o->search.step, "the first step, pixels")->capture_default_str();
  cmd->add_option("--min-step", o->search.min_step, "the last step, pixels")->capture_default_str();
  cmd->add_option("-o,--output", o->output, "write the refined pattern (.json or .xyw)");
  cmd->add_option("--name", o->name, "the refined pattern's name (default: START-perceptual)");
  add_reference_options(cmd, o->reference, 256);
  cmd->add_flag("--json", o->json, "print JSON");
  return [o, scenes](std::ostream& out) {
    if (!o->output.empty() && !is_pattern_path(o->output))
      throw Error(fmt::format("--output: '{}' must end in .json or .xyw", o->output));
    const Pattern start = resolve_pattern(o->pattern);
    validate(o->search, start);  // before the objective's references are rendered
    std::optional<PerceptualObjective> perceptual;
    std::optional<RenderedObjective> rendered;
    RefineObjective objective;
    if (scenes->count() > 0) {
      StudySettings s;
      s.scenes = o->scenes;
      std::tie(s.width, s.height) = parse_size(o->size, "--size", 1024);
      s.reference.samples = o->reference.settings.samples;
      s.reference.filter = o->reference.settings.filter;
      rendered.emplace(s, o->reference.source(), o->measure, start.footprint.size != 1);
      objective = refine_objective(*rendered);
    } else {
      if (!is_perceptual(o->objective))
        throw ParameterError("objective",
                             fmt::format(" '{}': refine searches under the perceptual objective "
                                         "(perceptual:key=value,...) or --scenes; E2's "
                                         "optimizer is `aapat optimize`",
                                         o->objective));
      perceptual.emplace(parse_perceptual(o->objective));
      objective = refine_objective(*perceptual);
    }
    RefineResult r;
    {
      Progress bar("refine");
      r = refine_pattern(start, objective, o->search, bar.callback());
    }
    if (!o->name.empty()) r.pattern.name = o->name;
    if (!o->output.empty()) save_pattern_file(r.pattern, o->output);
    const JsonObject doc = refine_json(objective, start, o->search, r);
    if (o->json) {
      out << json_text(doc);
      return;
    }
    out << fmt::format("objective {}\n{} {}: {:.6f} -> {:.6f} after {} evaluations", objective.text,
                       start.name, family(start), r.start_value, r.value, r.tries);
    if (o->search.weight_steps > 0)
      out << fmt::format(" ({:.6f} after the compass search, then {} weight steps)",
                         r.compass_value, r.gradient_steps);
    out << "\n";
    if (!o->output.empty()) out << "wrote " << o->output << "\n";
  };
}

}  // namespace aapat
