// `aapat eval PATTERN...`: E2 (Laine-Aila Eq. 5), the worst angle and n for
// each pattern; optionally the per-angle profile W(theta) E1(theta).
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/profile_plot.h"
#include "aapat/study/eval_study.h"
#include "aapat/study/perceptual_objective.h"
#include "cli/commands.h"
#include "cli/metric_options.h"

namespace aapat {

namespace {

struct EvalOptions {
  std::vector<std::string> patterns;
  MetricOptions metric;
  bool json = false, optimized_weights = false;
  std::string profile;
};

// Under the perceptual objective: its value and each kind's mean FLIP.
void run_perceptual_eval(const EvalOptions& o, std::ostream& out) {
  if (!o.metric.filter.empty() || !o.metric.acuity.empty() || !o.metric.norm.empty())
    throw ParameterError("objective",
                         ": the perceptual objective has no --filter, --acuity or --norm; give "
                         "its parameters in the spec (aapat list objectives)");
  if (!o.profile.empty() || o.optimized_weights)
    throw ParameterError("objective",
                         ": --profile and --optimized-weights are E2's; the perceptual objective "
                         "has neither");
  const PerceptualObjective objective(parse_perceptual(o.metric.objective));
  std::vector<Pattern> patterns;
  std::vector<PerceptualError> errors;
  for (const auto& name : o.patterns) {
    patterns.push_back(resolve_pattern(name));
    errors.push_back(objective.evaluate(patterns.back()));
  }
  const JsonObject doc = perceptual_eval_json(objective.spec(), patterns, errors);
  if (o.json) {
    out << json_text(doc);
    return;
  }
  size_t width = 22;
  for (const Pattern& p : patterns) width = std::max(width, p.name.size());
  out << fmt::format("objective {}\n{:<{}} {:<14} {:>6} {:>10}", objective.spec().text(), "pattern",
                     width, "family", "n", "perceptual");
  for (const PerceptualKind& k : errors.front().kinds) out << fmt::format(" {:>9}", k.name);
  out << "\n";
  for (size_t i = 0; i < patterns.size(); ++i) {
    out << fmt::format("{:<{}} {:<14} {:>6} {:>10.6f}", patterns[i].name, width,
                       family(patterns[i]), format_cost(samples_per_pixel(patterns[i])),
                       errors[i].value);
    for (const PerceptualKind& k : errors[i].kinds) out << fmt::format(" {:>9.6f}", k.flip);
    out << "\n";
  }
}

void run_eval(EvalOptions& o, std::ostream& out) {
  if (is_perceptual(o.metric.objective)) return run_perceptual_eval(o, out);
  if (!o.profile.empty() && !o.profile.ends_with(".svg") && !o.profile.ends_with(".csv"))
    throw Error(fmt::format("--profile: '{}' must end in .svg or .csv", o.profile));
  const Objective objective = o.metric.resolve();
  const Metric metric = objective.metric();
  std::vector<Pattern> patterns;
  for (const auto& name : o.patterns) patterns.push_back(resolve_pattern(name));

  const std::vector<PatternEvaluation> evaluations =
      evaluate_patterns(metric, patterns, o.optimized_weights, !o.profile.empty());
  // The JSON document is the result; the text table is printed from its rows.
  const JsonObject doc = eval_json(objective, metric.angle_count(), patterns, evaluations);
  if (o.json) {
    out << json_text(doc);
  } else {
    size_t width = 22;  // the name column, wide enough for an optimized pattern's name
    for (const JsonObject& row : doc["rows"])
      width = std::max(width, row["pattern"].get<std::string>().size());
    out << fmt::format("{}, {} angles\n{:<{}} {:<14} {:>6} {:>8} {:>12} {:>7}{}\n",
                       objective.caption(), doc["angles"].get<int>(), "pattern", width, "family",
                       "n", "E2", "worst angle", "kernel",
                       o.optimized_weights ? "  E2 opt. W" : "");
    for (const JsonObject& row : doc["rows"])
      out << fmt::format("{:<{}} {:<14} {:>6} {:>8.4f} {:>12g} {:>7}{}\n",
                         row["pattern"].get<std::string>(), width, row["family"].get<std::string>(),
                         format_cost(row["n"].get<double>()), row["e2"].get<double>(),
                         row["worst_angle_deg"].get<double>(), row["worst_kernel"].get<int>(),
                         row.contains("e2_optimized_weights")
                             ? fmt::format("  {:>10.4f}", row["e2_optimized_weights"].get<double>())
                             : "");
  }
  std::vector<ProfileSeries> series;
  for (size_t i = 0; i < patterns.size(); ++i)
    if (!o.profile.empty()) series.push_back({patterns[i].name, evaluations[i].worst_profile});
  if (!o.profile.empty()) {
    const std::string title = "W(theta) E1(theta), " + objective.caption();
    write_output(o.profile,
                 o.profile.ends_with(".svg") ? profile_svg(metric.acuity(), series, title)
                                             : profile_csv(metric.acuity(), series),
                 out);
    if (!o.json) out << "wrote " << o.profile << "\n";
  }
}

}  // namespace

Action add_eval_command(CLI::App& app) {
  auto* cmd = app.add_subcommand("eval", "evaluate E2 of patterns against a reference filter");
  auto o = std::make_shared<EvalOptions>();
  cmd->add_option("patterns", o->patterns, "catalog names or pattern files (.json)")->required();
  o->metric.add_to(cmd);
  cmd->add_flag("--json", o->json, "print JSON (docs/json.md): a row per pattern");
  cmd->add_flag("--optimized-weights", o->optimized_weights,
                "also the E2 with weights optimized for the same positions");
  cmd->add_option("--profile", o->profile,
                  "write W(theta) E1(theta) of all patterns to a .svg plot or .csv table");
  return [o](std::ostream& out) { run_eval(*o, out); };
}

}  // namespace aapat
