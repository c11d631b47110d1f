// `aapat study`: which objective predicts rendered error (study/objective_study.h).
// Prints, per budget, each objective's rank correlation with each rendered
// measure (Spearman, averaged over the scenes, with the range of the
// intervals) and the recommendation; the full table as Markdown, CSV, JSON,
// and a report page (--html).
#include <fmt/format.h>

#include <memory>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/core/text.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/study/objective_study.h"
#include "aapat/study/study_report.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/reference_options.h"

namespace aapat {
namespace {

struct StudyOptions {
  StudySettings settings;
  std::vector<std::string> compare;
  std::string budgets = "2,4,8", norms = "inf,2,4", size = "64", table, csv, html;
  ReferenceOptions reference;
  bool json = false, pairs = false;
};

std::vector<int> parse_budgets(const std::string& text) {
  std::vector<int> out;
  for (std::string_view item : split(text)) {
    const double n = parse_number(trim(item), "--budgets");
    if (n != std::floor(n)) throw Error(fmt::format("--budgets: {} is not a whole number", n));
    out.push_back(static_cast<int>(n));
  }
  return out;
}

std::vector<double> parse_norms(const std::string& text) {
  std::vector<double> out;
  for (std::string_view item : split(text)) out.push_back(parse_norm(trim(item), "--norms"));
  return out;
}

// The correlation table of one budget: one row per objective, one column per
// measure, each cell the mean Spearman over the scenes.
std::string summary_table(const StudyResult& r, const BudgetStudy& b) {
  std::string t = fmt::format(
      "{} samples per pixel, {} patterns: Spearman's rho between the "
      "objective and each rendered measure, mean over {} scenes\n",
      b.budget, b.patterns.size(), r.scenes.size());
  t += fmt::format("{:<26}", "objective");
  for (const char* m : kStudyMeasures) t += fmt::format(" {:>14}", m);
  t += fmt::format(" {:>8}\n", "mean");
  for (size_t o = 0; o < r.objectives.size(); ++o) {
    t += fmt::format("{:<26}", r.objectives[o].name());
    for (size_t m = 0; m < kStudyMeasures.size(); ++m)
      t += fmt::format(" {:>14.3f}", measure_spearman(b, int(o), int(m)).mean);
    t += fmt::format(" {:>8.3f}\n", b.mean_spearman[o]);
  }
  return t;
}

std::string recommendation(const StudyResult& r) {
  const size_t best = static_cast<size_t>(r.recommended), papers = static_cast<size_t>(r.papers);
  double runner_up = -INFINITY;
  size_t second = best;
  for (size_t o = 0; o < r.mean_spearman.size(); ++o)
    if (o != best && r.mean_spearman[o] > runner_up) runner_up = r.mean_spearman[o], second = o;
  std::string text = fmt::format(
      "recommended objective: {} (mean Spearman {:.3f} over every budget, scene and measure)",
      r.objectives[best].name(), r.mean_spearman[best]);
  if (second != best)
    text += fmt::format("; {:+.3f} over the next, {}", r.mean_spearman[best] - runner_up,
                        r.objectives[second].name());
  if (papers != best)
    text +=
        fmt::format("; {:+.3f} over the papers' {}",
                    r.mean_spearman[best] - r.mean_spearman[papers], r.objectives[papers].name());
  return text + "\n";
}

// Every correlation: budget, objective, scene, measure, both statistics and intervals.
std::string correlations_csv(const StudyResult& r) {
  std::string csv =
      "budget,objective,scene,measure,spearman,spearman_low,spearman_high,kendall,kendall_low,"
      "kendall_high\n";
  for (const BudgetStudy& b : r.budgets)
    for (const StudyCorrelation& c : b.correlations)
      csv += fmt::format("{},{},{},{},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f},{:.4f}\n", b.budget,
                         r.objectives[c.objective].name(), r.scenes[c.scene],
                         kStudyMeasures[c.measure], c.r.spearman.value, c.r.spearman.low,
                         c.r.spearman.high, c.r.kendall.value, c.r.kendall.low, c.r.kendall.high);
  return csv;
}

// Every pair of objectives in how well they predict the mean FLIP, paired
// over the scenes (objective_pairs), from the study's seed.
std::vector<ObjectivePair> flip_pairs(const StudyResult& r, const StudySettings& s) {
  const auto flip =
      std::find(kStudyMeasures.begin(), kStudyMeasures.end(), std::string_view("flip"));
  return objective_pairs(r, static_cast<int>(flip - kStudyMeasures.begin()), s.resamples, s.seed);
}

std::string pairs_table(const StudyResult& r, const std::vector<ObjectivePair>& pairs) {
  std::string t =
      "Spearman's rho with FLIP, objective a against objective b, paired over the scenes "
      "(mean over the budgets per scene; 95% bootstrap interval of the mean difference over "
      "scenes):\n";
  for (const ObjectivePair& p : pairs)
    if (p.a < p.b)
      t += fmt::format(
          "  {} - {}: {:+.4f} [{:+.4f}, {:+.4f}], a higher in {} of {} scenes, sign p = {:.3g}\n",
          r.objectives[p.a].name(), r.objectives[p.b].name(), p.rho.mean_difference, p.rho.low,
          p.rho.high, p.rho.items - p.rho.lower - p.rho.ties, p.rho.items, p.rho.sign_p);
  return t;
}

// pairs: flip_pairs(r, ...) with --pairs, else none.
JsonObject study_json(const StudyResult& r, const StudyOptions& o,
                      const std::vector<ObjectivePair>& pairs) {
  JsonObject doc = json_report("study");
  JsonObject objectives = JsonObject::array();
  for (size_t i = 0; i < r.objectives.size(); ++i)
    objectives.push_back({{"name", r.objectives[i].name()},
                          {"filter", r.objectives[i].filter},
                          {"acuity", r.objectives[i].acuity},
                          {"norm", format_norm(r.objectives[i].norm)},
                          {"perceptual", r.objectives[i].perceptual},
                          {"mean_spearman", r.mean_spearman[i]}});
  JsonObject budgets = JsonObject::array();
  for (const BudgetStudy& b : r.budgets) {
    JsonObject patterns = JsonObject::array();
    for (const StudyPattern& p : b.patterns) {
      JsonObject measures = JsonObject::array();
      for (const auto& m : p.measures) measures.push_back(m);
      patterns.push_back({{"name", p.name},
                          {"source", p.source},
                          {"objectives", p.objective},
                          {"measures", measures}});
    }
    JsonObject correlations = JsonObject::array();
    for (const StudyCorrelation& c : b.correlations)
      correlations.push_back({{"objective", c.objective},
                              {"scene", r.scenes[c.scene]},
                              {"measure", kStudyMeasures[c.measure]},
                              {"spearman", c.r.spearman.value},
                              {"spearman_interval", {c.r.spearman.low, c.r.spearman.high}},
                              {"kendall", c.r.kendall.value},
                              {"kendall_interval", {c.r.kendall.low, c.r.kendall.high}}});
    budgets.push_back({{"budget", b.budget},
                       {"patterns", patterns},
                       {"mean_spearman", b.mean_spearman},
                       {"correlations", correlations}});
  }
  doc.update(JsonObject{{"scenes", r.scenes},
                        {"measures", kStudyMeasures},
                        {"width", o.settings.width},
                        {"height", o.settings.height},
                        {"frames", o.settings.frames},
                        {"seed", o.settings.seed},
                        {"reference", describe_reference(o.settings.reference)},
                        {"objectives", objectives},
                        {"recommended", r.recommended},
                        {"budgets", budgets}});
  if (o.pairs) {
    JsonObject rows = JsonObject::array();
    for (const ObjectivePair& p : pairs)
      rows.push_back({{"a", p.a}, {"b", p.b}, {"rho", paired_comparison_json(p.rho)}});
    doc["flip_rho_pairs"] = rows;
  }
  return doc;
}

// --compare: every objective and rendered measure (mean over the scenes) of
// the named patterns, as a Markdown table.
void run_compare(StudyOptions& o, std::ostream& out) {
  std::vector<StudyPattern> patterns;
  for (const std::string& name : o.compare)
    patterns.push_back({name, "", resolve_pattern(name), {}, {}, {}});
  patterns = measure_patterns(std::move(patterns), o.settings, o.reference.source());
  const std::vector<StudyObjective> objectives = study_objectives(o.settings);
  if (o.json) {
    out << json_text(study_compare_json(o.settings, objectives, patterns));
    return;
  }
  std::string t = "| pattern |", rule = "| --- |";
  for (const StudyObjective& ob : objectives) t += " " + ob.name() + " |", rule += " ---: |";
  for (const char* m : kStudyMeasures) t += fmt::format(" {} |", m), rule += " ---: |";
  t += "\n" + rule + "\n";
  for (const StudyPattern& p : patterns) {
    t += "| " + p.name + " |";
    for (const double v : p.objective) t += fmt::format(" {:.4f} |", v);
    for (size_t m = 0; m < kStudyMeasures.size(); ++m) {
      double sum = 0;
      for (const auto& per_scene : p.measures) sum += per_scene[m];
      t += fmt::format(" {:.4f} |", sum / double(p.measures.size()));
    }
    t += "\n";
  }
  // Each pattern after the first against it, per measure, paired over the scenes.
  const std::vector<MeasureComparisons> c = compare_with_first(patterns, o.settings);
  for (size_t k = 0; k < c.size(); ++k)
    for (size_t q = 0; q < kStudyMeasures.size(); ++q) {
      const PairedComparison& p = c[k][q];
      t += fmt::format(
          "\n{} against {}, {}: lower in {} of {} scenes ({} ties), mean difference {:+.5f} "
          "[{:+.5f}, {:+.5f}], ratio {:.4f}, sign test p = {:.3g}",
          patterns[k + 1].name, patterns[0].name, kStudyMeasures[q], p.lower, p.items, p.ties,
          p.mean_difference, p.low, p.high, p.mean_ratio, p.sign_p);
    }
  if (!c.empty()) t += "\n";
  out << t;
}

void run_study(StudyOptions& o, std::ostream& out) {
  o.settings.budgets = parse_budgets(o.budgets);
  o.settings.norms = parse_norms(o.norms);
  std::tie(o.settings.width, o.settings.height) = parse_size(o.size, "--size", 1024);
  o.settings.reference.samples = o.reference.settings.samples;
  o.settings.reference.filter = o.reference.settings.filter;
  if (!o.html.empty() && !o.html.ends_with(".html"))
    throw Error(fmt::format("--html: '{}' must end in .html", o.html));
  validate(o.settings);
  if (!o.compare.empty()) return run_compare(o, out);
  StudyResult r;
  {
    Progress bar("study");
    r = objective_study(o.settings, o.reference.source(), bar.callback());
  }
  std::string text;
  for (const BudgetStudy& b : r.budgets) text += summary_table(r, b) + "\n";
  text += recommendation(r);
  const std::vector<ObjectivePair> pairs =
      o.pairs ? flip_pairs(r, o.settings) : std::vector<ObjectivePair>{};
  if (o.pairs) text += "\n" + pairs_table(r, pairs);
  if (!o.table.empty()) write_output(o.table, "```\n" + text + "```\n", out);
  if (!o.csv.empty()) write_output(o.csv, correlations_csv(r), out);
  if (!o.html.empty())
    write_output(o.html, study_report_html(r, o.settings, o.reference.source()), out);
  out << (o.json ? json_text(study_json(r, o, pairs)) : text);
}

}  // namespace

Action add_study_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "study",
      "which objective predicts rendered error: patterns x objectives x rendered measures");
  auto o = std::make_shared<StudyOptions>();
  cmd->add_option("--budgets", o->budgets, "samples per pixel, a comma list (P(1,1,n))")
      ->capture_default_str();
  cmd->add_option("--patterns", o->settings.patterns, "patterns per budget, at least")
      ->capture_default_str();
  cmd->add_option("--include", o->settings.include,
                  "more patterns, catalog names or files, where their samples per pixel fit");
  cmd->add_option("--compare", o->compare,
                  "instead of the study: every objective and rendered measure (mean over the "
                  "scenes) of these patterns, as a table");
  cmd->add_option("--perceptual", o->settings.perceptual,
                  "perceptual objectives to study beside E2's (specs: perceptual:key=value,...)");
  cmd->add_flag("--pairs", o->pairs,
                "every pair of objectives: the difference in rho with FLIP, paired over scenes");
  cmd->add_option("--filter", o->settings.filter, "the objectives' reference filter")
      ->capture_default_str();
  cmd->add_option("--acuity", o->settings.acuities, "the objectives' acuity tables")
      ->capture_default_str();
  cmd->add_option("--norms", o->norms, "the objectives' norms over angles: inf, 2, 4, ...")
      ->capture_default_str();
  cmd->add_option("--scenes", o->settings.scenes,
                  "triangle, circle (animations), halfplane (every edge angle), or render scenes")
      ->capture_default_str();
  cmd->add_option("--size", o->size, "WIDTHxHEIGHT, or N for N x N")->capture_default_str();
  cmd->add_option("--frames", o->settings.frames, "frames per animated scene")
      ->capture_default_str();
  cmd->add_option("--starts", o->settings.starts, "optimizer starts per objective and budget")
      ->capture_default_str();
  cmd->add_option("--resamples", o->settings.resamples,
                  "bootstrap resamples: of the patterns (the study), of the scenes (--compare)")
      ->capture_default_str();
  add_seed_option(cmd, o->settings.seed, "random seed");
  add_reference_options(cmd, o->reference, 256);
  cmd->add_option("--table", o->table, "the correlation tables (markdown)");
  cmd->add_option("--csv", o->csv, "every correlation with its intervals (CSV)");
  cmd->add_option("--html", o->html, "the report as one self-contained page (.html)");
  cmd->add_flag("--json", o->json,
                "print every pattern, objective, measure and correlation as JSON");
  // --compare prints its own table (or --json); the study's files are not its.
  auto* compare = cmd->get_option("--compare");
  for (const char* study_file : {"--table", "--csv", "--html"})
    compare->excludes(cmd->get_option(study_file));
  return [o](std::ostream& out) { run_study(*o, out); };
}

}  // namespace aapat
