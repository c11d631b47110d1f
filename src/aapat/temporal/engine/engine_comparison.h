// The rendered comparison study: K jitter sequences, each rendered through
// an engine preset's full nonlinear pipeline (engine_taa.h) on the same M
// scenes under the same motion, with per-scene measures (rmse over every
// frame's pixels, mean flicker, mean FLIP), and every sequence after the
// first compared with the first per measure: the scenes where it is lower,
// the mean difference with a paired bootstrap interval over the scenes and
// an exact sign test (analyze/paired_comparison.h). `aapat sequence compare`
// and Python's sequence_compare run it; its JSON is one document.
//
// Scenes are any scene spec or file; random_scene_specs names M generated
// ones (the render registry's random-shapes), so that a study on unseen
// content is one command, with its seeds.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "aapat/analyze/paired_comparison.h"
#include "aapat/io/json_report.h"
#include "aapat/render/reference.h"
#include "aapat/temporal/engine/engine_taa.h"
#include "aapat/temporal/model/pan_distribution.h"
#include "aapat/temporal/sequence/sequence.h"
#include "aapat/work/work_items.h"

namespace aapat {

// The measures compared, each lower = better, in the order of every row.
inline constexpr std::array<const char*, 3> kComparisonMeasures = {"rmse", "flicker", "flip"};
using ComparisonMeasures = std::array<double, kComparisonMeasures.size()>;
inline constexpr int kMaxComparisonScenes = 1024;

// The motions a comparison takes by name, each with what it measures (the
// faces' help is comparison_motion_help()):
//  - static: the still scene in steady state (after the warm-up);
//  - cut: the still scene's first frames after a cut (no warm-up), each
//    measure the mean over every phase of the sequence the cut can fall on
//    (the sequence started at each of its frames in turn), and its worst;
//  - random-pan: each scene its own pan, random_pan_velocities(M,
//    max_speed, seed);
//  - resonant: each scene panned at every velocity of resonant_velocities()
//    (render pixels per frame, times the ratio on the display), in steady
//    state, each measure the mean over them and its worst.
struct ComparisonMotion {
  const char* name;
  const char* summary;
};
inline constexpr std::array<ComparisonMotion, 4> kComparisonMotions = {{
    {"static", "the still scene in steady state"},
    {"cut", "the frames after a cut, averaged over every phase it can fall on, and at the worst"},
    {"random-pan", "each scene its own pan from the seed, components within the max speed"},
    {"resonant",
     "every scene panned at each resonant velocity (0, 1/4, 1/3, 1/2 render px/frame per axis, "
     "both signs, and R2's step), averaged over them, and at the worst"},
}};
// "static (...), cut (...), random-pan (...), resonant (...), or a motion
// spec for every scene".
std::string comparison_motion_help();
// Whether a motion renders each scene several ways (cut: from every phase;
// resonant: at every velocity), so that each scene has a worst.
bool renders_several_ways(const std::string& motion);

struct EngineComparison {
  EngineTaa taa;
  std::vector<std::string> scenes;  // scene specs or files
  // A name of kComparisonMotions or a motion spec (render/motion.h) for
  // every scene.
  std::string motion = "static";
  int width = 64, height = 64;
  int frames = 16, warmup = 64;
  ReferenceSettings reference{256, "mitchell", 1};  // as `aapat animate`'s
  uint64_t seed = 1;
  double max_speed = kDefaultRandomPanSpeed;
  int resamples = 2000;
  double confidence = 0.95;
};

// One sequence on one scene rendered several ways (after a cut: from every
// starting phase; resonant: at every velocity): each way's measures, and
// per measure the largest and which way gave it.
struct MeasureSpread {
  std::vector<ComparisonMeasures> each;
  ComparisonMeasures worst{};
  std::array<int, kComparisonMeasures.size()> worst_at{};
};

struct ComparedScene {
  std::string scene, motion;
  std::vector<ComparisonMeasures> measures;  // per sequence (the mean over the ways)
  // After a cut or at the resonances, per sequence: every phase or velocity.
  std::vector<MeasureSpread> spread;
};

using SequencePairs = std::array<PairedComparison, kComparisonMeasures.size()>;

struct EngineComparisonResult {
  std::vector<std::string> sequences;
  // What the preset's engine would not run (engine_sequence_warnings).
  std::vector<std::string> warnings;
  std::vector<Vec2> velocities;  // resonant: render pixels per frame
  std::vector<ComparedScene> scenes;
  // Each sequence after the first against the first, per measure: the
  // means, and (after a cut or at the resonances) each scene's worst.
  std::vector<SequencePairs> against_first, against_first_worst;
};

// Shapes in each generated scene unless a face is told otherwise.
inline constexpr int kDefaultRandomSceneShapes = 6;

// "random-shapes:count=SHAPES,seed=SEED+i" for i = 0 .. count-1. Throws
// ParameterError naming "random-scenes" or "shapes" out of range.
std::vector<std::string> random_scene_specs(int count, int shapes, uint64_t seed);

// The scenes a face names: those given, or `random_scenes` generated ones
// (random_scene_specs); ParameterError naming "scene" for both or neither.
std::vector<std::string> comparison_scenes(const std::vector<std::string>& given, int random_scenes,
                                           int shapes, uint64_t seed);

// Throws Error (ParameterError naming the setting) before any work: no
// scene or too many, fewer than two sequences, a motion it cannot make, a
// size, frame count or warm-up out of range.
void validate(const EngineComparison& c, size_t sequences);

// The comparison's scenes resolved once, each with its motion and its run
// settings, and every reference they have needed kept in memory (by scene and
// frame seed), so that each sequence rendered on them reads the same
// references, rendered once: a comparison of K sequences, or a search that
// renders hundreds. Call validate first.
class PreparedScenes {
 public:
  PreparedScenes(const EngineComparison& comparison, const ReferenceSource& references);
  size_t size() const { return scenes_.size(); }
  const std::string& motion(size_t scene) const { return motions_[scene]; }
  // One sequence on scene i under the preset: the mean over the ways it is
  // rendered (after a cut: its starting phases; resonant: the velocities;
  // else one), and every way's measures into `spread`.
  ComparisonMeasures render(size_t scene, const Sequence& s, const EngineTaa& taa,
                            MeasureSpread* spread = nullptr);
  // Whether a scene is rendered several ways (a cut, the resonances).
  bool spread() const { return cut_ || resonant_; }
  // Drops scene i's references (a comparison done with it).
  void forget(size_t scene);

 private:
  struct Way {
    EngineRun run;
    std::map<uint64_t, Image> memo;  // references by frame seed
  };
  std::vector<std::vector<Way>> scenes_;  // per scene, per velocity
  std::vector<std::string> motions_;
  bool cut_ = false, resonant_ = false;
  ReferenceSource source_;
};

// The sequence started at frame `phase`: frames phase, phase + 1, ... in turn.
Sequence started_at(const Sequence& s, int phase);

// progress: (renders done, renders, "SEQUENCE on SCENE") after each render.
EngineComparisonResult compare_under_engine(const std::vector<Sequence>& sequences,
                                            const EngineComparison& comparison,
                                            const ReferenceSource& references = {},
                                            const ItemsProgress& progress = {});

// `aapat sequence compare --json` and Python's sequence_compare: the settings
// (taa, taa_settings, ratio, motion, size, frames, warmup, reference,
// resamples, confidence), measures, sequences, resonant: velocities [[x,
// y]] (render px/frame), scenes [{scene, motion, rows [{sequence, rmse,
// flicker, flip, after a cut: worst_phase {rmse, flicker, flip} and
// worst_phase_at {MEASURE: phase}, resonant: worst_velocity {...} and
// worst_velocity_at {MEASURE: [x, y]}, per_velocity [{rmse, flicker,
// flip}]}]}], and against_first (and after a cut or resonant,
// against_first_worst: each scene's worst) [{sequence, against, MEASURE:
// {lower, ties, scenes, mean_difference, low, high, mean_ratio, sign_p}}],
// and warnings [text] when there are any.
JsonObject engine_comparison_json(const EngineComparison& c, const EngineComparisonResult& r);

// The settings every rendered comparison reports: taa, taa_settings, ratio,
// motion, width, height, frames, warmup, reference, seed.
JsonObject comparison_settings_json(const EngineComparison& c);

}  // namespace aapat
