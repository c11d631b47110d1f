// `aapat sequence compare`: the rendered comparison study
// (temporal/engine/engine_comparison.h): jitters rendered under an engine
// preset on the same scenes, each after the first against the first with
// win counts, paired intervals and a sign test.
#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <ostream>
#include <tuple>

#include "aapat/core/filter_catalog.h"
#include "aapat/render/animation.h"
#include "aapat/temporal/engine/engine_comparison.h"
#include "aapat/temporal/engine/engine_taa_settings.h"
#include "aapat/temporal/sequence/sequence_json.h"
#include "cli/app.h"
#include "cli/commands.h"
#include "cli/progress.h"
#include "cli/reference_options.h"
#include "cli/sequence_options.h"

namespace aapat {

void add_sequence_compare(CLI::App* parent, std::function<void(std::ostream&)>& action) {
  auto* cmd = parent->add_subcommand(
      "compare",
      "render jitters through an engine preset on the same scenes (given, or generated "
      "random-shapes): per-scene RMSE, flicker and FLIP, and each sequence after the first "
      "against it: scenes lower, the mean difference with a paired bootstrap interval, a sign "
      "test");
  struct Options {
    std::vector<std::string> sequences, scenes, taa_set;
    std::string taa, motion = EngineComparison{}.motion, size = "64";
    double ratio = 1, max_speed = EngineComparison{}.max_speed;
    int random_scenes = 0, shapes = 6, frames = EngineComparison{}.frames,
        warmup = EngineComparison{}.warmup, resamples = EngineComparison{}.resamples;
    uint64_t seed = 1;
    ReferenceOptions reference;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("sequences", o->sequences,
                  "sequence files or generator specs, at least two (a generator without frames= "
                  "takes the upscaler's phases for --ratio); the first is the baseline")
      ->required();
  cmd->add_option("--taa", o->taa, "the engine preset (ue4, fsr2, godot, bevy)")->required();
  cmd->add_option("--taa-set", o->taa_set, "KEY=VALUE: override one of the preset's settings");
  auto* ratio = cmd->add_option("--ratio", o->ratio, "display / render resolution (>= 1)")
                    ->capture_default_str();
  auto* scene = cmd->add_option("--scene", o->scenes,
                                "a scene spec or file, repeatable (the same scenes for every "
                                "sequence)");
  auto* random = cmd->add_option(
      "--random-scenes", o->random_scenes,
      fmt::format("N generated scenes random-shapes:count=SHAPES,seed=SEED+i (1 to {})",
                  kMaxComparisonScenes));
  scene->excludes(random);
  cmd->add_option("--shapes", o->shapes, "--random-scenes: shapes a scene")->capture_default_str();
  cmd->add_option("--motion", o->motion,
                  "static (steady state), cut (the frames after a cut), random-pan (each scene "
                  "its own pan from --seed, components within --max-speed), or a motion spec for "
                  "every scene")
      ->capture_default_str();
  cmd->add_option("--max-speed", o->max_speed, "random-pan: the largest component, px/frame")
      ->capture_default_str();
  add_seed_option(cmd, o->seed, "the random scenes' first seed, the pans' and the bootstrap's")
      ->capture_default_str();
  cmd->add_option("--size", o->size, "WIDTHxHEIGHT, or N for N x N")->capture_default_str();
  cmd->add_option("--frames", o->frames, "frames measured per render")->capture_default_str();
  cmd->add_option("--warmup", o->warmup, "frames rendered before the measured ones")
      ->capture_default_str();
  cmd->add_option("--resamples", o->resamples, "bootstrap resamples of the scenes")
      ->capture_default_str();
  o->reference.settings = EngineComparison{}.reference;
  add_reference_options(cmd, o->reference, EngineComparison{}.reference.samples);
  cmd->add_flag("--json", o->json, "print JSON");
  action = [o, cmd, ratio](std::ostream& out) {
    if (!cmd->parsed()) return;
    EngineComparison c;
    c.taa = make_engine_taa(o->taa, o->ratio, parse_taa_overrides(o->taa_set));
    if (o->scenes.empty() && o->random_scenes == 0)
      throw Error("sequence compare: give the scenes (--scene, repeatable) or --random-scenes N");
    c.scenes =
        o->scenes.empty() ? random_scene_specs(o->random_scenes, o->shapes, o->seed) : o->scenes;
    c.motion = o->motion;
    std::tie(c.width, c.height) = parse_size(o->size, "--size", kMaxAnimationSize);
    c.frames = o->frames;
    c.warmup = o->warmup;
    c.reference = o->reference.settings;
    c.seed = o->seed;
    c.max_speed = o->max_speed;
    c.resamples = o->resamples;
    std::vector<Sequence> sequences;
    for (const std::string& spec : o->sequences) {
      std::string warning;
      sequences.push_back(
          resolve_sequence_for_ratio(spec, o->ratio, ratio->count() ? &warning : nullptr));
      if (!warning.empty()) warnings() << "aapat: warning: " << warning << "\n";
    }
    validate(c, sequences.size());  // before any render
    EngineComparisonResult r;
    {
      Progress bar("compare");
      r = compare_under_engine(sequences, c, o->reference.source(), bar.callback());
    }
    if (o->json) {
      out << json_text(engine_comparison_json(c, r));
      return;
    }
    out << fmt::format("{}, {} on {} scenes of {}x{}, {} frames after {} warm-up; {}\n",
                       engine_taa_text(c.taa), c.motion, c.scenes.size(), c.width, c.height,
                       c.frames, c.motion == "cut" ? 0 : c.warmup, describe_reference(c.reference));
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
    for (size_t k = 1; k < r.sequences.size(); ++k)
      for (size_t q = 0; q < kComparisonMeasures.size(); ++q) {
        const PairedComparison& p = r.against_first[k - 1][q];
        out << fmt::format(
            "{} against {}, {}: lower in {} of {} scenes ({} ties), mean difference {:+.5f} "
            "[{:+.5f}, {:+.5f}] ({:g} % interval), ratio {:.4f}, sign test p = {:.3g}\n",
            r.sequences[k], r.sequences[0], kComparisonMeasures[q], p.lower, p.items, p.ties,
            p.mean_difference, p.low, p.high, 100 * c.confidence, p.mean_ratio, p.sign_p);
      }
  };
}

}  // namespace aapat
