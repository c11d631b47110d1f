// The rendered sequence commands, which share their scene options:
//  - `aapat sequence compare`: jitters rendered under an engine preset on the
//    same scenes, each after the first against the first with win counts,
//    paired intervals and a sign test (temporal/engine/engine_comparison.h);
//  - `aapat sequence search`: a jitter searched on that rendered error
//    against a baseline (temporal/search/rendered_search.h).
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <ostream>
#include <tuple>

#include "aapat/core/filter_catalog.h"
#include "aapat/render/animation.h"
#include "aapat/temporal/engine/engine_comparison.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/search/rendered_search.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "cli/app.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/reference_options.h"
#include "cli/sequence_options.h"

namespace aapat {
namespace {

// The preset, the scenes and their motion, the renders' size and frames.
struct ComparisonOptions {
  std::vector<std::string> scenes, taa_set;
  std::string taa, motion = EngineComparison{}.motion, size = "64";
  double ratio = 1, max_speed = EngineComparison{}.max_speed;
  int random_scenes = 0, shapes = kDefaultRandomSceneShapes, frames = EngineComparison{}.frames,
      warmup = EngineComparison{}.warmup;
  uint64_t seed = 1;
  ReferenceOptions reference;
  CLI::Option* ratio_option = nullptr;

  void add_to(CLI::App* cmd) {
    cmd->add_option("--taa", taa, "the engine preset (" + engine_preset_names() + ")")->required();
    cmd->add_option("--taa-set", taa_set, "KEY=VALUE: override one of the preset's settings");
    ratio_option = cmd->add_option("--ratio", ratio, "display / render resolution (>= 1)")
                       ->capture_default_str();
    auto* scene = cmd->add_option(
        "--scene", scenes, "a scene spec or file, repeatable (the same scenes for every sequence)");
    auto* random = cmd->add_option(
        "--random-scenes", random_scenes,
        fmt::format("N generated scenes random-shapes:count=SHAPES,seed=SEED+i (1 to {})",
                    kMaxComparisonScenes));
    scene->excludes(random);
    cmd->add_option("--shapes", shapes, "--random-scenes: shapes a scene")->capture_default_str();
    cmd->add_option("--motion", motion, comparison_motion_help())->capture_default_str();
    cmd->add_option("--max-speed", max_speed, "random-pan: the largest component, px/frame")
        ->capture_default_str();
    add_seed_option(cmd, seed, "the random scenes' first seed, the pans' and the bootstrap's")
        ->capture_default_str();
    cmd->add_option("--size", size, "WIDTHxHEIGHT, or N for N x N")->capture_default_str();
    cmd->add_option("--frames", frames, "frames measured per render")->capture_default_str();
    cmd->add_option("--warmup", warmup, "frames rendered before the measured ones")
        ->capture_default_str();
    reference.settings = EngineComparison{}.reference;
    add_reference_options(cmd, reference, EngineComparison{}.reference.samples);
  }

  EngineComparison make() const {
    EngineComparison c;
    c.taa = make_engine_taa(taa, ratio, parse_taa_overrides(taa_set));
    c.scenes = comparison_scenes(scenes, random_scenes, shapes, seed);
    c.motion = motion;
    std::tie(c.width, c.height) = parse_size(size, "--size", kMaxAnimationSize);
    c.frames = frames;
    c.warmup = warmup;
    c.reference = reference.settings;
    c.seed = seed;
    c.max_speed = max_speed;
    return c;
  }

  Sequence sequence(const std::string& spec) const {
    std::string warning;
    Sequence s =
        resolve_sequence_for_ratio(spec, ratio, ratio_option->count() ? &warning : nullptr);
    if (!warning.empty()) warnings() << "aapat: warning: " << warning << "\n";
    return s;
  }
};

std::string comparison_caption(const EngineComparison& c) {
  return fmt::format("{}, {} on {} scenes of {}x{}, {} frames after {} warm-up; {}",
                     engine_taa_text(c.taa), c.motion, c.scenes.size(), c.width, c.height, c.frames,
                     c.motion == "cut" ? 0 : c.warmup, describe_reference(c.reference));
}

}  // namespace

void add_sequence_compare(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "compare",
      "render jitters through an engine preset on the same scenes (given, or generated "
      "random-shapes): per-scene RMSE, flicker and FLIP, and each sequence after the first "
      "against it: scenes lower, the mean difference with a paired bootstrap interval, a sign "
      "test");
  struct Options {
    std::vector<std::string> sequences;
    ComparisonOptions comparison;
    int resamples = EngineComparison{}.resamples;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("sequences", o->sequences,
                  "sequence files or generator specs, at least two (a generator without frames= "
                  "takes the upscaler's phases for --ratio); the first is the baseline")
      ->required();
  o->comparison.add_to(cmd);
  cmd->add_option("--resamples", o->resamples, "bootstrap resamples of the scenes")
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "print JSON");
  action = [o, cmd](std::ostream& out) {
    if (!cmd->parsed()) return;
    EngineComparison c = o->comparison.make();
    c.resamples = o->resamples;
    std::vector<Sequence> sequences;
    for (const std::string& spec : o->sequences) sequences.push_back(o->comparison.sequence(spec));
    validate(c, sequences.size());  // before any render
    EngineComparisonResult r;
    {
      Progress bar("compare");
      r = compare_under_engine(sequences, c, o->comparison.reference.source(), bar.callback());
    }
    for (const std::string& w : r.warnings) warnings() << "aapat: warning: " << w << "\n";
    if (o->json) {
      out << json_text(engine_comparison_json(c, r));
      return;
    }
    out << comparison_caption(c) << "\n";
    size_t width = 8;
    for (const std::string& s : r.sequences) width = std::max(width, s.size());
    out << fmt::format("{:<{}}", "sequence", width);
    for (const char* m : kComparisonMeasures)
      out << fmt::format(" {:>12}", fmt::format("mean {}", m));
    out << "\n";
    for (size_t k = 0; k < r.sequences.size(); ++k) {
      out << fmt::format("{:<{}}", r.sequences[k], width);
      for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
        double sum = 0;
        for (const ComparedScene& s : r.scenes) sum += s.measures[k][q];
        out << fmt::format(" {:>12.5f}", sum / static_cast<double>(r.scenes.size()));
      }
      out << "\n";
    }
    // The means, then (after a cut or at the resonances) each scene's worst.
    const auto against = [&](const std::vector<SequencePairs>& comparisons, const char* what) {
      for (size_t k = 1; k <= comparisons.size(); ++k)
        for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
          const PairedComparison& p = comparisons[k - 1][q];
          out << fmt::format(
              "{} against {}, {}{}: lower in {} of {} scenes ({} ties), mean difference {:+.5f} "
              "[{:+.5f}, {:+.5f}] ({:g} % interval), ratio {:.4f}, sign test p = {:.3g}\n",
              r.sequences[k], r.sequences[0], what, kComparisonMeasures[q], p.lower, p.items,
              p.ties, p.mean_difference, p.low, p.high, 100 * c.confidence, p.mean_ratio, p.sign_p);
        }
    };
    against(r.against_first, "");
    against(r.against_first_worst, c.motion == "cut" ? "worst phase's " : "worst velocity's ");
  };
}

void add_sequence_search(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "search",
      "search a jitter on rendered error: a compass search whose objective renders it through "
      "an engine preset on the scenes against a baseline (the mean log ratio of RMSE and "
      "flicker, losses weighted by 1 + --loss)");
  struct Options {
    std::string start, against, output;
    std::vector<std::string> also_motions;
    ComparisonOptions comparison;
    double step = RenderedSearch{}.step, min_step = RenderedSearch{}.min_step,
           loss = RenderedSearch{}.loss, jitter_bound = RenderedSearch{}.jitter_bound;
    int max_tries = 0;
    bool worst = false, unbiased = false, json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("start", o->start,
                  "the start: a sequence file or generator spec of one-sample frames")
      ->required();
  cmd->add_option("--against", o->against,
                  "the baseline rendered on the same scenes (default: the preset's own jitter)");
  o->comparison.add_to(cmd);
  cmd->add_option("--step", o->step, "the first step, pixels")->capture_default_str();
  cmd->add_option("--min-step", o->min_step, "the smallest step, pixels")->capture_default_str();
  cmd->add_option("--loss", o->loss, "a scene lost weighs 1 + LOSS times a scene won")
      ->capture_default_str();
  cmd->add_option("--jitter-bound", o->jitter_bound, "every coordinate within +-BOUND pixels")
      ->capture_default_str();
  cmd->add_option("--max-tries", o->max_tries, "end after this many tries (0: no limit)")
      ->capture_default_str();
  cmd->add_option("--also-motion", o->also_motions,
                  "search under this motion too (repeatable; the objective is the mean over the "
                  "motions): " +
                      comparison_motion_help());
  cmd->add_flag("--worst", o->worst,
                "search on each scene's worst phase (--motion cut) or resonant velocity "
                "(--motion resonant), not the mean over them");
  cmd->add_flag("--unbiased", o->unbiased,
                "keep the frames' mean jitter at (0, 0), as XeSS asks of a jitter sequence "
                "(each trial is rendered centred)");
  cmd->add_option("-o,--output", o->output, "write the sequence found (.json)");
  cmd->add_flag("--json", o->json, "print JSON");
  action = [o, cmd](std::ostream& out) {
    if (!cmd->parsed()) return;
    if (!o->output.empty() && !o->output.ends_with(".json"))
      throw Error(fmt::format("--output: '{}' must end in .json (a sequence file)", o->output));
    RenderedSearch s;
    s.comparison = o->comparison.make();
    s.start = o->comparison.sequence(o->start);
    s.baseline = o->comparison.sequence(o->against.empty() ? s.comparison.taa.jitter : o->against);
    s.step = o->step;
    s.min_step = o->min_step;
    s.loss = o->loss;
    s.jitter_bound = o->jitter_bound;
    s.max_tries = o->max_tries;
    s.worst = o->worst;
    s.unbiased = o->unbiased;
    s.also_motions = o->also_motions;
    validate(s);  // before any render
    RenderedSearchResult r;
    {
      Progress bar("search");
      r = search_rendered(s, o->comparison.reference.source(), bar.callback());
    }
    for (const std::string& w : r.warnings) warnings() << "aapat: warning: " << w << "\n";
    if (!o->output.empty()) save_sequence_file(r.best, o->output);
    if (o->json) {
      out << json_text(rendered_search_json(s, r));
      return;
    }
    out << comparison_caption(s.comparison) << "\n";
    out << fmt::format(
        "searched {} from {} against {}: objective {:.6f} -> {:.6f}; {} tries, {} kept\n",
        r.best.period(), s.start.name, s.baseline.name, r.start_value, r.value, r.tries, r.kept);
    for (int f = 0; f < r.best.period(); ++f) {
      const Vec2 j = r.best.frames[static_cast<size_t>(f)].sets[0][0];
      out << fmt::format("  frame {:>3}: ({:>9.5f}, {:>9.5f})\n", f, j.x, j.y);
    }
    if (!o->output.empty()) out << "wrote " << o->output << "\n";
  };
}

}  // namespace aapat
