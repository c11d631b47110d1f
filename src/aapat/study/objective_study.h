// Which objective predicts rendered error? For each sample budget n, a set
// of one-pixel patterns P(1,1,n) (the catalog's, patterns optimized under
// each objective, random point sets with equal weights), each measured by
// every objective (filter x acuity table x norm over angles) and rendered
// with its own weights on a suite of scenes (the rotating triangle and the
// translating circle, Hasselgren's animations; a half-plane through the
// centre rotating over every edge angle; the spiral, the circles, the
// checkerboard), every rendering against its dense reference: RMSE, maximum
// deviation, 1 - SSIM, and the squared-error histogram's tail (the RMS of
// the deviations of 32 levels and more). The rank correlations (Spearman,
// Kendall) between each objective and each rendered measure across the
// patterns, with bootstrap intervals, say which objective ranks patterns as
// their renderings do.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "aapat/analyze/paired_comparison.h"
#include "aapat/core/pattern.h"
#include "aapat/render/reference.h"
#include "aapat/study/progress.h"
#include "aapat/study/rank_correlation.h"

namespace aapat {

struct StudyObjective {
  std::string filter, acuity;
  double norm;  // Metric::kMaxNorm for the maximum
  // A perceptual objective's spec as given (study/perceptual_objective.h);
  // empty for an E2 objective (filter x acuity x norm).
  std::string perceptual;
  std::string name() const;  // "laine-aila L_inf", "uniform:step=1 L_2", the perceptual spec
};

// The rendered measures, each larger = worse.
inline constexpr std::array<const char*, 5> kStudyMeasures = {"rmse", "max_deviation",
                                                              "one_minus_ssim", "tail_rms", "flip"};
using StudyMeasures = std::array<double, kStudyMeasures.size()>;

struct StudySettings {
  std::vector<int> budgets{2, 4, 8};  // samples per pixel, P(1,1,n)
  int patterns = 30;                  // per budget, at least
  std::vector<std::string> include;   // more patterns (catalog names, files) where n fits
  std::string filter = "mitchell";
  std::vector<std::string> acuities{"laine-aila", "linear:step=1", "uniform:step=1"};
  std::vector<double> norms{std::numeric_limits<double>::infinity(), 2, 4};  // max, L2, L4
  // Perceptual objectives to study beside the E2 ones (specs; none by default).
  std::vector<std::string> perceptual;
  // triangle, circle (animations), halfplane (rotating through every edge
  // angle), and any render scene (spiral, circles, checkerboard, ...).
  std::vector<std::string> scenes{"triangle", "circle",  "halfplane",
                                  "spiral",   "circles", "checkerboard"};
  int width = 64, height = 64;  // pixels
  int frames = 16;              // per animated scene
  int starts = 8;               // optimizer starts per objective and budget
  int resamples = 1000;
  uint64_t seed = 1;
  ReferenceSettings reference{256, "mitchell", 1};
};

struct StudyPattern {
  std::string name, source;  // source: "catalog", "optimized for ...", "generator ..."
  Pattern pattern;
  std::vector<double> objective;        // per objective: E2
  std::vector<StudyMeasures> measures;  // per scene: kStudyMeasures
  std::vector<double> profile;          // W E1 every degree (uniform table, the objectives' filter)
};

struct StudyCorrelation {
  int objective, scene, measure;
  RankCorrelation r;
};

struct BudgetStudy {
  int budget = 0;
  std::vector<StudyPattern> patterns;
  std::vector<StudyCorrelation> correlations;
  std::vector<double> mean_spearman;  // per objective, over scenes and measures
};

// One objective against one measure at one budget: Spearman's rho averaged
// over the scenes (NaN when no scene has it), and the lowest and highest
// ends of its scenes' bootstrap intervals. The one place the tables, the
// JSON and the report average a budget's correlations.
struct MeasureSpearman {
  double mean = 0, low = 0, high = 0;
};
MeasureSpearman measure_spearman(const BudgetStudy& b, int objective, int measure);

struct StudyResult {
  std::vector<StudyObjective> objectives;
  std::vector<std::string> scenes;
  std::vector<BudgetStudy> budgets;
  std::vector<double> mean_spearman;  // per objective, over budgets, scenes, measures
  int recommended = 0;                // the objective with the highest mean_spearman
  int papers = 0;                     // the papers' objective (laine-aila, the maximum)
};

// Throws ParameterError naming a setting out of range before any work.
void validate(const StudySettings& s);

// The study's objectives (filter x acuity table x norm) in their order.
std::vector<StudyObjective> study_objectives(const StudySettings& s);

// Every objective and rendered measure of the given patterns (any family:
// each renders with its own weights), without correlations: the catalog's
// comparisons.
std::vector<StudyPattern> measure_patterns(std::vector<StudyPattern> patterns,
                                           const StudySettings& settings,
                                           const ReferenceSource& references);
// Each pattern after the first against the first, per rendered measure,
// paired over the scenes (analyze/paired_comparison.h: scenes lower, the mean
// difference with a bootstrap interval from settings.resamples draws seeded
// by settings.seed, an exact sign test): `study --compare`'s against_first.
using MeasureComparisons = std::array<PairedComparison, kStudyMeasures.size()>;
std::vector<MeasureComparisons> compare_with_first(const std::vector<StudyPattern>& patterns,
                                                   const StudySettings& settings);
StudyResult objective_study(const StudySettings& settings, const ReferenceSource& references,
                            const StudyProgress& progress = {});

// The mean over the settings' scenes of one rendered measure (kStudyMeasures)
// of a pattern rendered with its own weights: an objective measured on
// content instead of charts, for `aapat refine --scenes`. The references are
// rendered (or read from the cache) and FLIP's half of each prepared once,
// here; each call renders the pattern on every scene in parallel and sums
// in scene order, so a value does not depend on the thread count. Throws
// ParameterError for settings out of range or an unknown measure.
struct SceneFrames;
inline constexpr int kRenderedObjectiveSize = 128;  // pixels a side, the faces' default
inline constexpr const char* kRenderedObjectiveMeasure = "flip";  // the faces' default
class RenderedObjective {
 public:
  RenderedObjective(const StudySettings& settings, const ReferenceSource& references,
                    std::string measure = kRenderedObjectiveMeasure, bool corner = false);
  double operator()(const Pattern& pattern) const;
  // "flip over 36 scenes at 128x128 (reference 256 spp)": provenance's record.
  std::string text() const;
  const StudySettings& settings() const { return settings_; }

 private:
  StudySettings settings_;
  std::string measure_name_;
  size_t measure_ = 0;
  std::shared_ptr<const SceneFrames> scenes_;
};

// Objective a against objective b in how well they predict one rendered
// measure: per scene, Spearman's rho of each (averaged over the budgets),
// paired over the scenes (analyze/paired_comparison.h; "lower" counts the
// scenes where a's rho is below b's, the interval is the bootstrap over
// scenes of the mean difference a - b). Positive: a predicts it better.
struct ObjectivePair {
  int a = 0, b = 0;
  PairedComparison rho;  // ours: a's per-scene rho, theirs: b's
};
std::vector<ObjectivePair> objective_pairs(const StudyResult& result, int measure, int resamples,
                                           uint64_t seed);

}  // namespace aapat
