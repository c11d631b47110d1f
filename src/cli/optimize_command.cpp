// `aapat optimize`: multi-start optimization of a family (Laine-Aila Sec. 5),
// or polishing of an existing pattern.
#include <fmt/format.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <memory>
#include <ostream>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/lattice.h"
#include "aapat/generate/enumerate.h"
#include "aapat/io/json_report.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/pattern_svg.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/lattice_search.h"
#include "aapat/optimize/multistart.h"
#include "aapat/study/optimize_run.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/search/pan_search.h"
#include "aapat/temporal/search/search_json.h"
#include "aapat/temporal/search/still_search.h"
#include "aapat/temporal/sequence/sequence_generators.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "aapat/work/work_items.h"
#include "cli/app.h"
#include "cli/commands.h"
#include "cli/metric_options.h"
#include "cli/option_modes.h"
#include "cli/progress.h"
#include "cli/sequence_options.h"

namespace aapat {
namespace {

std::string optimize_text(const OptimizeRunResult& r) {
  const StartRecord& best = r.best_start();
  std::string text =
      fmt::format("optimized {} under the {}\n", r.description, r.objective.caption());
  text += fmt::format(
      "{} starts ran in {:.2f} s; best start {}: E2 {:.4f} -> {:.4f} in {} iterations\n",
      r.search.starts.size(), r.seconds, best.start, best.run.initial_e2, best.run.final_e2,
      best.run.iterations);
  if (r.search.polished_from > 0)
    text +=
        fmt::format("(the heuristic's best {:.5f}, polished by the minimax descent to {:.5f})\n",
                    r.search.polished_from, best.run.final_e2);
  if (r.unconstrained_e2)
    text += fmt::format(
        "non-negative weights: E2 {:.4f}; unconstrained from the same start: {:.4f} "
        "(cost {:+.4f})\n",
        best.run.final_e2, *r.unconstrained_e2, best.run.final_e2 - *r.unconstrained_e2);
  if (const auto& L = r.lattice) {
    text += fmt::format(
        "lattice 1/{}{}: continuous E2 {:.4f}, snapped {:.4f}, lattice optimum {:.4f} ({:+.4f}; "
        "best of {} lattice starts, start {}, {} moves)\n",
        L->steps, L->profile.empty() ? "" : fmt::format(" for {}", L->profile), L->continuous_e2,
        L->snapped_e2, L->lattice_e2, L->lattice_e2 - L->continuous_e2, L->starts, L->best_start,
        L->moves);
    if (L->layout)
      text += fmt::format(
          "{}: {}x{} pixel grid, {}x MSAA, {} samples per pixel, the resolve reads {} per "
          "output pixel\n",
          L->profile, L->layout->grid_w, L->layout->grid_h, L->layout->sample_count,
          format_cost(samples_per_pixel(r.best)), format_cost(L->layout->reads()));
  }
  const Pattern& p = r.best;
  text += fmt::format("{}  {}  n = {}\n", p.name, family(p), format_cost(samples_per_pixel(p)));
  for (const Vec2& s : p.sets[0])
    text += fmt::format("  {:>9.5f} {:>9.5f}  {}\n", s.x, s.y, site_name(s));
  text += "  weights:";
  for (double w : p.weights[0]) text += fmt::format(" {:.5f}", w);
  return text + "\n";
}

std::string starts_csv(const MultiStartResult& result, const Objective& objective) {
  std::string csv = "start,initial_e2,final_e2,iterations,seconds,objective\n";
  for (const auto& r : result.starts)
    csv += fmt::format("{},{:.10g},{:.10g},{},{:.4f},\"{}\"\n", r.start, r.run.initial_e2,
                       r.run.final_e2, r.run.iterations, r.seconds, objective.text());
  return csv;
}

// The defaults are the library's: a default-constructed OptimizeRunSettings
// (and SequenceSearch for --sequence), as Python's are.
struct OptimizeOptions {
  std::string pattern, family, placement, seeds = OptimizeRunSettings{}.seeds,
                                          method = method_key(OptimizerSettings{}.method);
  std::string output, csv, svg, api, name;
  MetricOptions metric;
  int lattice = OptimizeRunSettings{}.lattice;
  int starts = kDefaultSearchStarts, threads = OptimizeRunSettings{}.threads,
      iterations = OptimizerSettings{}.max_iterations;
  uint64_t seed = OptimizeRunSettings{}.seed;
  double time_limit = OptimizeRunSettings{}.time_limit;
  std::vector<int> lock;
  bool weights_only = false, nonnegative = false, starts_given = false, json = false;
  bool border_samples = false;
  // --sequence K: a jitter / alternating-MSAA sequence instead of a pattern.
  int sequence = 0, samples_per_frame = 1;
  double flicker_weight = SequenceSearch{}.flicker_weight;
  double jitter_bound = SequenceSearch{}.jitter_bound;
  std::optional<double> jitter_radius;
  std::string frame_measure{frame_measure_name(SequenceSearch{}.frame_measure)};
  bool equal_weights = false;
  ModelOptions model;
  // --ratio R: the jitter of an upscale from display / R, reconstructed by --reconstruct.
  double ratio = 1;
  bool ratio_given = false;
  std::string reconstruct{kDefaultReconstruction};
  // --taa PRESET: the search under motion (temporal/search/pan_search.h).
  std::string taa, from;
  std::vector<std::string> taa_set, velocities;
  double step = PanSequenceSearch{}.step, min_step = PanSequenceSearch{}.min_step;
};

// `optimize --sequence K --taa PRESET`: the compass search on the pan model.
void run_pan_search(const OptimizeOptions& o, std::ostream& out) {
  if (o.samples_per_frame != 1)
    throw Error("--taa searches one-sample frames: give no --samples-per-frame");
  const Objective objective = o.metric.resolve();
  const Metric metric = objective.metric();
  PanSequenceSearch s;
  s.taa = make_engine_taa(o.taa, o.ratio, parse_taa_overrides(o.taa_set));
  for (const std::string& v : o.velocities) s.velocities.push_back(parse_velocity(v));
  s.step = o.step;
  s.min_step = o.min_step;
  s.jitter_bound = o.jitter_bound;
  PanSequenceSearchResult r;
  try {
    s.start = pan_search_start(o.sequence, o.from);
    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    Progress bar("pan search");
    arena.execute([&] { r = search_sequence_under_pans(s, metric, bar.callback()); });
  } catch (const ParameterError& e) {
    throw Error(fmt::format("--{}{}", e.parameter(), e.detail()));
  }
  for (const std::string& warning : r.warnings) warnings() << "aapat: warning: " << warning << "\n";
  if (!o.name.empty()) r.best.name = o.name;
  if (!o.output.empty()) save_sequence_file(r.best, o.output);
  if (o.json) {
    out << json_text(pan_search_json(s, objective, r));
    return;
  }
  out << fmt::format("searched {} frames under the pan model of {}; {}\n", o.sequence,
                     engine_taa_text(s.taa), objective.caption());
  out << fmt::format("steady mean E2 per velocity (px/frame), {} -> the result:\n", s.start.name);
  for (size_t i = 0; i < r.velocities.size(); ++i)
    out << fmt::format("  {:>12}  {:.5f} -> {:.5f} ({:+.2f} %)\n",
                       fmt::format("{:g},{:g}", r.velocities[i].x, r.velocities[i].y),
                       r.start_values[i], r.values[i], 100 * (r.values[i] / r.start_values[i] - 1));
  out << fmt::format("  {:>12}  {:.5f} -> {:.5f} ({:+.2f} %); {} steps tried, {} kept\n", "mean",
                     r.start_value, r.value, 100 * (r.value / r.start_value - 1), r.tries, r.kept);
  for (int f = 0; f < r.best.period(); ++f) {
    const Vec2 j = r.best.frames[static_cast<size_t>(f)].sets[0][0];
    out << fmt::format("  frame {:>3}: ({:>9.5f}, {:>9.5f})\n", f, j.x, j.y);
  }
  if (!o.output.empty()) out << "wrote " << o.output << "\n";
}

// `optimize --sequence K`: the temporal search (temporal/search/still_search.h).
void run_sequence_search(const OptimizeOptions& o, std::ostream& out) {
  if (!o.pattern.empty() || !o.family.empty())
    throw Error("--sequence searches K one-pixel frames: give no PATTERN and no --family");
  if (!o.output.empty() && !o.output.ends_with(".json"))
    throw Error(fmt::format("--output: '{}' must end in .json (a sequence file)", o.output));
  if (o.method != "descent" && o.method != "slsqp")
    throw Error(fmt::format("--method {}: a sequence is searched with slsqp (its epigraph form)",
                            o.method));
  if (!o.taa.empty()) return run_pan_search(o, out);
  if (!o.taa_set.empty() || !o.velocities.empty() || !o.from.empty())
    throw Error("--taa-set, --velocity and --from belong to the search under motion: give --taa");
  const Objective objective = o.metric.resolve();
  const Metric metric = objective.metric();
  SequenceSearch s;
  s.frames = o.sequence;
  s.samples_per_frame = o.samples_per_frame;
  s.model = o.model.make();
  s.flicker_weight = o.flicker_weight;
  s.jitter_bound = o.jitter_bound;
  s.jitter_radius = o.jitter_radius;
  s.frame_measure = parse_frame_measure(o.frame_measure);
  s.optimize_weights = !o.equal_weights;
  s.starts = o.starts;
  s.seed = o.seed;
  s.iterations = o.iterations;
  if (!o.api.empty()) s.profile = &api_profile(o.api);
  if (o.reconstruct != kDefaultReconstruction && !o.ratio_given)
    throw Error("--reconstruct: the reconstruction of an upscale; give --ratio R with it");
  if (o.ratio_given) s.upscale = make_upscale(o.ratio, o.reconstruct);
  SequenceSearchResult r;
  try {
    tbb::task_arena arena(o.threads > 0 ? o.threads : tbb::task_arena::automatic);
    Progress bar("sequence");
    arena.execute([&] { r = optimize_sequence(s, metric, bar.callback()); });
  } catch (const ParameterError& e) {
    throw Error(fmt::format("--{}{}", e.parameter(), e.detail()));
  }
  for (const std::string& warning : r.warnings) warnings() << "aapat: warning: " << warning << "\n";
  if (!o.name.empty()) r.best.name = o.name;
  if (!o.output.empty()) save_sequence_file(r.best, o.output);
  if (o.json) {
    out << json_text(sequence_search_json(s, o.model.text(), objective, r));
    return;
  }
  out << fmt::format("optimized {} frames of {} sample(s) under {}{}, {}\n", s.frames,
                     s.samples_per_frame, o.model.text(),
                     s.upscale ? fmt::format(", upscaled {:g}x through {}", s.upscale->ratio,
                                             s.upscale->reconstruction.name())
                               : "",
                     objective.caption());
  out << fmt::format(
      "J = {} E2 + {} x mean flicker: {:.5f} (worst E2 {:.5f}, mean E2 {:.5f}, mean flicker "
      "{:.5f}); Halton(2,3) of the same length {:.5f}; best of {} starts: start {}\n",
      o.frame_measure, s.flicker_weight, r.objective, r.worst_e2, r.mean_e2, r.flicker,
      r.halton_objective, s.starts, r.best_start);
  if (r.continuous_objective)
    out << fmt::format("on the 1/16 lattice of {}: J {:.5f} before snapping, {:.5f} after\n", o.api,
                       *r.continuous_objective, r.objective);
  for (int f = 0; f < r.best.period(); ++f) {
    out << fmt::format("  frame {:>3}:", f);
    const Pattern& frame = r.best.frames[static_cast<size_t>(f)];
    for (size_t i = 0; i < frame.sets[0].size(); ++i)
      out << fmt::format(" ({:>9.5f}, {:>9.5f})", frame.sets[0][i].x, frame.sets[0][i].y)
          << (frame.sets[0].size() > 1 ? fmt::format(" w {:.4f}", frame.weights[0][i]) : "");
    out << "\n";
  }
  if (!o.output.empty()) out << "wrote " << o.output << "\n";
}

void run_optimize(OptimizeOptions& o, const CLI::Option* starts_option, std::ostream& out) {
  if (o.sequence > 0) return run_sequence_search(o, out);
  check_family_or_pattern(!o.family.empty(), !o.pattern.empty());
  if (!o.output.empty() && !is_pattern_path(o.output))
    throw Error(fmt::format("--output: '{}' must end in .json or .xyw", o.output));
  const Objective objective = o.metric.resolve();
  OptimizeRunSettings s;
  s.family = o.family;
  s.placement = o.placement;
  s.seeds = o.seeds;
  // Seeds from a file: the same as polishing it, in the family asked for.
  if (!o.family.empty() && o.seeds.ends_with(".json")) o.pattern = o.seeds;
  if (!o.pattern.empty()) {
    s.start = resolve_pattern(o.pattern);
    s.start_label = o.pattern;
  }
  if (starts_option->count() > 0 || o.pattern.empty()) s.starts = o.starts;
  s.seed = o.seed;
  s.lock = o.lock;
  s.strictly_inside = !o.border_samples;
  s.threads = o.threads;
  s.lattice = o.lattice;
  s.api = o.api;
  s.optimizer.method = parse_method(o.method);
  s.optimizer.max_iterations = o.iterations;
  s.optimizer.weights_only = o.weights_only;
  s.optimizer.nonnegative_weights = o.nonnegative;
  s.time_limit = o.time_limit;
  OptimizeRunResult r;
  {
    Progress bar("optimize");
    r = optimize_run(objective, s, bar.callback());
  }
  if (!o.name.empty()) r.best.name = o.name;
  // With --json the document alone goes to stdout.
  std::ostream discard(nullptr);
  std::ostream& text = o.json ? discard : out;
  // The files first: one that cannot be written (a tile as .xyw) fails the
  // command before any of its report is printed.
  std::string wrote;
  if (!o.output.empty()) {
    save_pattern_file(r.best, o.output);
    wrote += "wrote " + o.output + "\n";
  }
  if (!o.svg.empty()) {
    write_output(o.svg, pattern_svg(r.best), out);
    wrote += "wrote " + o.svg + "\n";
  }
  if (!o.csv.empty()) {
    write_output(o.csv, starts_csv(r.search, r.objective), out);
    wrote += "wrote " + o.csv + "\n";
  }
  text << optimize_text(r) << wrote;
  if (o.json) out << json_text(optimize_run_json(r));
}

}  // namespace

// optimize's modes: a pattern search, a sequence search under the linear
// model (at a render scale with --ratio), and a sequence search under motion
// through an engine's TAA. What each takes, and what to give instead.
OptionModes optimize_option_modes() {
  const std::vector<std::string> pattern = {
      "family",         "placement",   "starts", "seed",    "seeds", "lock",
      "time-limit",     "iterations",  "method", "lattice", "api",   "weights-only",
      "border-samples", "nonnegative", "csv",    "svg"};
  const std::vector<std::string> sequence = {"sequence",       "samples-per-frame",
                                             "flicker-weight", "jitter-bound",
                                             "jitter-radius",  "equal-weights",
                                             "frame-measure",  "model",
                                             "alpha",          "window",
                                             "resolve",        "ratio",
                                             "reconstruct",    "starts",
                                             "seed",           "iterations",
                                             "method",         "api"};
  const std::vector<std::string> motion = {
      "sequence", "taa",      "taa-set", "velocity",     "from",
      "step",     "min-step", "ratio",   "jitter-bound", "samples-per-frame"};
  std::map<std::string, std::string> not_pattern, not_sequence, not_motion;
  for (const std::string& o : sequence) not_pattern[o] = "add --sequence K to search a sequence";
  for (const std::string& o : motion)
    if (!not_pattern.contains(o)) not_pattern[o] = "add --sequence K --taa PRESET";
  for (const std::string& o : pattern)
    if (std::find(sequence.begin(), sequence.end(), o) == sequence.end())
      not_sequence[o] = "a sequence search takes none of the pattern search's options";
  for (const char* o : {"taa-set", "velocity", "from", "step", "min-step"})
    not_sequence[o] = "add --taa PRESET: it belongs to the search under motion";
  for (const std::string& o : pattern) not_motion[o] = "the search under motion takes none";
  for (const char* o : {"starts", "seed", "iterations", "method"})
    not_motion[o] =
        "the search under motion is a compass search from --from, with --step and "
        "--min-step";
  for (const char* o : {"model", "alpha", "window", "resolve", "flicker-weight", "jitter-radius",
                        "equal-weights", "frame-measure", "reconstruct"})
    not_motion[o] = "the preset's own TAA is the model: change it with --taa-set KEY=VALUE";
  OptionModes t;
  t.command = "optimize";
  t.selectors = {"sequence", "taa"};
  t.shared = {"objective", "filter", "acuity", "norm", "threads", "output", "json", "name"};
  t.modes = {
      {"the pattern search (--family or PATTERN)", pattern, not_pattern, {"--family", "P(1,1,2)"}},
      {"the sequence search (--sequence)", sequence, not_sequence, {"--sequence", "4"}},
      {"the search under motion (--sequence with --taa)",
       motion,
       not_motion,
       {"--sequence", "4", "--taa", "ue4"}},
  };
  return t;
}

Action add_optimize_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "optimize", "optimize positions and weights: a family from random starts, or a pattern");
  auto o = std::make_shared<OptimizeOptions>();
  cmd->add_option("pattern", o->pattern, "catalog name or pattern file to polish");
  cmd->add_option("--family", o->family, "family to search, e.g. 'P(4,1+,2)'");
  cmd->add_option("--placement", o->placement,
                  "sites of the base pixel's samples: inside, left, right, bottom, top, "
                  "bottom-left, ... (FLIPQUAD: left,right,bottom,top)");
  o->metric.add_to(cmd);
  cmd->add_option("--starts", o->starts, "random starts (run in parallel)")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxStarts));
  add_seed_option(cmd, o->seed, "random seed");
  cmd->add_option("--seeds", o->seeds,
                  "seed patterns: jittered, poisson, uniform, or a pattern file (.json) whose "
                  "starts after the first are jittered by up to 0.1 pixel")
      ->capture_default_str();
  cmd->add_option("--lock", o->lock, "samples of the base pixel (set 0) to keep fixed, e.g. 0,2")
      ->delimiter(',');
  cmd->add_option("--time-limit", o->time_limit, "seconds for the whole run (0: none)")
      ->check(CLI::Range(0.0, kMaxTimeLimit));
  cmd->add_option("--iterations", o->iterations, "iterations per start at most")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxIterations));
  cmd->add_option("--method", o->method,
                  "descent (Laine-Aila heuristic), minimax (eps-active min-norm descent), anneal, "
                  "or the epigraph form with NLopt: slsqp, mma, ccsaq")
      ->capture_default_str()
      ->check(CLI::IsMember({"descent", "minimax", "anneal", "slsqp", "mma", "ccsaq"}));
  cmd->add_option("--threads", o->threads, "threads (0: all cores)")
      ->check(CLI::Range(0, kMaxThreads));
  cmd->add_option("--lattice", o->lattice,
                  "then search positions on the 1/N-pixel lattice (16: programmable MSAA)")
      ->check(CLI::Range(kMinLatticeSteps, kMaxLatticeSteps));
  cmd->add_option("--api", o->api,
                  "with --lattice: the pattern must fit this API profile (d3d12-tier1, "
                  "d3d12-tier2, vulkan, metal, gl)");
  cmd->add_flag("--weights-only", o->weights_only, "keep positions, optimize weights (Opt W)");
  cmd->add_flag("--border-samples", o->border_samples,
                "let samples of a family without shared borders onto the pixel's border (the "
                "papers' closed pixel; default: strictly inside, as plain MSAA needs)");
  cmd->add_flag("--nonnegative", o->nonnegative, "keep weights >= 0 and report the E2 this costs");
  cmd->add_option("-o,--output", o->output, "write the best pattern (.json)");
  cmd->add_option("--name", o->name,
                  "the name of the pattern or sequence found (default: what it is: family or "
                  "length, objective or ratio, seed)");
  cmd->add_option("--csv", o->csv,
                  "write every start: start, initial E2, final E2, iterations, seconds");
  cmd->add_option("--svg", o->svg, "write a drawing of the best pattern");
  cmd->add_flag("--json", o->json, "print the result as JSON (docs/json.md)");
  cmd->add_option("--sequence", o->sequence,
                  "search a sequence of K frames instead (TAA jitter, alternating MSAA; "
                  "docs/temporal.md): worst steady E2 + mean flicker under --model")
      ->check(CLI::Range(1, kMaxSequenceFrames));
  cmd->add_option("--samples-per-frame", o->samples_per_frame,
                  "with --sequence: samples in each frame (1: a jitter)")
      ->capture_default_str()
      ->check(CLI::Range(1, kMaxSearchSamplesPerFrame));
  cmd->add_option("--flicker-weight", o->flicker_weight,
                  "with --sequence: lambda of J = worst E2 + lambda mean flicker")
      ->capture_default_str();
  cmd->add_option("--jitter-bound", o->jitter_bound,
                  "with --sequence: every jitter coordinate within +-B pixels (below 1/2: lower "
                  "error on moving content under an engine's clamp, higher when still)")
      ->capture_default_str();
  cmd->add_option("--jitter-radius", o->jitter_radius,
                  "with --sequence: every jitter within R pixels of the pixel centre (what an "
                  "engine's clamp prefers on moving content; not with --ratio)");
  cmd->add_flag("--equal-weights", o->equal_weights,
                "with --sequence and several samples per frame: keep each frame's weights equal "
                "(default: they move, summing to 1)");
  cmd->add_option(
         "--frame-measure", o->frame_measure,
         "with --sequence: the frames' E2 in J, worst (steady frame) or mean (over phases)")
      ->capture_default_str()
      ->check(CLI::IsMember({"worst", "mean"}));
  o->model.add_to(cmd);
  cmd->add_option("--ratio", o->ratio,
                  "with --sequence: optimize the jitter of an upscale from display / R (R >= 1), "
                  "each display pixel reconstructed from the render pixels around it "
                  "(docs/temporal.md, the linear model of upscaling)")
      ->each([o](const std::string&) { o->ratio_given = true; });
  cmd->add_option("--reconstruct", o->reconstruct,
                  "with --ratio: the reconstruction filter over render pixels")
      ->capture_default_str();

  cmd->add_option("--taa", o->taa,
                  "with --sequence: search under motion instead, for this engine preset (" +
                      engine_preset_names() +
                      "): the pan model's steady mean E2 averaged over --velocity "
                      "(docs/temporal.md, \"Under motion\")");
  cmd->add_option("--taa-set", o->taa_set,
                  "with --taa: KEY=VALUE, override one of the preset's settings");
  cmd->add_option("--velocity", o->velocities,
                  "with --taa: DX,DY display pixels per frame, repeatable (default: those of "
                  "`aapat sequence pan`, still 0,0 among them)");
  cmd->add_option("--from", o->from,
                  "with --taa: the start, a sequence file or spec (default halton:frames=K)");
  cmd->add_option("--step", o->step, "with --taa: the compass search's first step (pixels)")
      ->capture_default_str();
  cmd->add_option("--min-step", o->min_step, "with --taa: its last step (pixels)")
      ->capture_default_str();

  auto* starts_option = cmd->get_option("--starts");
  enforce_option_modes(cmd, optimize_option_modes(), [cmd] {
    return cmd->get_option("--sequence")->count() == 0 ? size_t{0}
           : cmd->get_option("--taa")->count() > 0     ? size_t{2}
                                                       : size_t{1};
  });
  return [o, starts_option](std::ostream& out) { run_optimize(*o, starts_option, out); };
}

}  // namespace aapat
