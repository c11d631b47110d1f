#include "aapat/study/objective_study.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <numeric>

#include "aapat/core/acuity.h"
#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"
#include "aapat/io/pattern_json.h"
#include "aapat/io/scene_json.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/multistart.h"
#include "aapat/render/image_error.h"
#include "aapat/render/image_flip.h"
#include "aapat/render/renderer.h"
#include "aapat/render/ssim.h"
#include "aapat/study/perceptual_objective.h"
#include "aapat/work/byte_codec.h"
#include "aapat/work/work_items.h"

namespace aapat {

struct SceneFrames {
  std::vector<std::vector<Scene>> frames;
  std::vector<std::vector<Image>> references, shifted;
  std::vector<std::vector<FlipReference>> flip_references, flip_shifted;
};

namespace {

// The deviations a rendering is judged by beyond its RMSE: the RMS of those
// of 32 levels (12.5%) and more, the histogram's tail.
constexpr int kTailLevel = 32;

bool one_pixel(const Pattern& p, int n) {
  return p.set_count() == 1 && p.footprint.size == 1 && !p.footprint.plus &&
         static_cast<int>(p.sets[0].size()) == n;
}

// The frames of a study scene at width x height.
std::vector<Scene> frames_of(const std::string& scene, int width, int height, int frames) {
  std::vector<Scene> out;
  if (scene == "triangle" || scene == "circle") {
    for (int f = 0; f < frames; ++f)
      out.push_back(animation_frame(scene, width, height, f, frames));
  } else if (scene == "halfplane") {
    // Every edge angle: the normal turns by 180 / frames degrees a frame,
    // offset from the axes so that no frame is axis-aligned by accident.
    const Vec2 centre{(width - 1) / 2.0, (height - 1) / 2.0};
    for (int f = 0; f < frames; ++f)
      out.push_back(HalfPlaneScene{centre, 180.0 * (f + 0.37) / frames, 0.21});
  } else {
    out.push_back(resolve_scene(scene, width, height));
  }
  return out;
}

// The patterns of one budget: the catalog's and the included ones that are
// P(1,1,n), the optimum found under each objective, then random point sets
// with equal weights until there are enough.
std::vector<StudyPattern> budget_patterns(const StudySettings& s,
                                          const std::vector<StudyObjective>& objectives, int n) {
  std::vector<StudyPattern> out;
  for (const auto& entry : pattern_registry().entries()) {
    std::string name = entry.info.name;
    if (name == "grid-NxN") {
      const int k = static_cast<int>(std::lround(std::sqrt(double(n))));
      if (k * k != n || k == 2) continue;  // grid-2x2 is box2x2
      name = fmt::format("grid-{}x{}", k, k);
    }
    const Pattern p = catalog_pattern(name);
    if (one_pixel(p, n)) out.push_back({name, "catalog", p, {}, {}, {}});
  }
  for (const std::string& spec : s.include) {
    const Pattern p = resolve_pattern(spec);
    if (one_pixel(p, n)) out.push_back({spec, "included", p, {}, {}, {}});
  }
  const FamilySpec family = parse_family(fmt::format("P(1,1,{})", n), "");
  // One search per objective, all their starts at once (multistart_all).
  std::vector<Metric> metrics;
  metrics.reserve(objectives.size());  // the jobs point at them
  std::vector<MultiStartJob> jobs;
  std::vector<size_t> searched;  // the E2 objectives: the perceptual ones have no optimizer here
  for (size_t k = 0; k < objectives.size(); ++k) {
    const StudyObjective& o = objectives[k];
    if (!o.perceptual.empty()) continue;
    searched.push_back(k);
    const Metric& metric =
        metrics.emplace_back(make_filter(o.filter), make_acuity(o.acuity), o.norm);
    OptimizerSettings settings;
    settings.method = o.norm == Metric::kMaxNorm ? Method::kSlsqp : Method::kDescent;
    settings.max_iterations = o.norm == Metric::kMaxNorm ? 1000 : 4000;
    jobs.push_back({&metric, s.starts, s.seed,
                    family_seeds(family, SeedKind::kJittered, s.seed, metric.filter()), settings});
  }
  const std::vector<MultiStartResult> searches = multistart_all(jobs);
  for (size_t j = 0; j < searched.size(); ++j) {
    const size_t k = searched[j];
    Pattern p = pattern_of(searches[j].best_problem);
    p.name = fmt::format("opt-{}-{}", n, objectives[k].name());
    out.push_back({p.name, "optimized for " + objectives[k].name(), p, {}, {}, {}});
  }
  const std::vector<std::string> generators = {"random", "n-rooks", "poisson", "best-candidate",
                                               "semi-jittered:amount=0.7"};
  for (uint64_t seed = s.seed; static_cast<int>(out.size()) < s.patterns; ++seed)
    for (const std::string& g : generators) {
      if (static_cast<int>(out.size()) >= s.patterns) break;
      if (g.starts_with("semi-jittered") || g == "jittered") {
        const int k = static_cast<int>(std::lround(std::sqrt(double(n))));
        if (k * k != n) continue;
      }
      const std::string name = fmt::format("{} #{}", g, seed);
      out.push_back({name,
                     "generator " + g,
                     points_to_pattern(generate_points(g, n, seed), name),
                     {},
                     {},
                     {}});
    }
  return out;
}

// One pattern's rendered measures on one scene: every frame against its
// reference, the deviations of all frames together.
StudyMeasures render_measures(const Pattern& p, const std::vector<Scene>& frames,
                              const std::vector<Image>& references,
                              const std::vector<FlipReference>& flip_references, int width,
                              int height) {
  Sampling sampling;
  sampling.pattern = p;
  ImageError total;
  double pixels = 0, ssim_sum = 0, flip_sum = 0;
  for (size_t f = 0; f < frames.size(); ++f) {
    const Image image = render(frames[f], width, height, sampling, std::nullopt);
    const ImageError e = compare(image, references[f]);
    for (int i = 0; i < 256; ++i) total.count[i] += e.count[i];
    total.max_deviation = std::max(total.max_deviation, e.max_deviation);
    pixels += static_cast<double>(image.values.size());
    ssim_sum += std::min(width, height) >= kSsimWindow ? ssim(image, references[f]) : 1.0;
    flip_sum += flip_mean(image, flip_references[f]);
  }
  summarize(total, pixels);
  double tail = 0;
  for (int i = kTailLevel; i < 256; ++i) tail += total.contribution[i];
  const double n = static_cast<double>(frames.size());
  return {total.rmse, double(total.max_deviation), 1 - ssim_sum / n, std::sqrt(tail), flip_sum / n};
}

}  // namespace

std::string StudyObjective::name() const {
  if (!perceptual.empty()) return perceptual;
  return fmt::format("{} L{}", acuity, norm == Metric::kMaxNorm ? "inf" : format_norm(norm));
}

void validate(const StudySettings& s) {
  if (s.budgets.empty()) throw ParameterError("budgets", ": name at least one sample budget");
  for (const int n : s.budgets)
    if (n < 1 || n > 64) throw ParameterError("budgets", fmt::format(" {}: expected 1 to 64", n));
  if (s.patterns < 3 || s.patterns > 1000)
    throw ParameterError("patterns", fmt::format(" {}: expected 3 to 1000 per budget", s.patterns));
  if (s.acuities.empty() || s.norms.empty() || s.scenes.empty())
    throw ParameterError("objectives", ": name at least one acuity table, norm and scene");
  if (s.width < 8 || s.width > 1024 || s.height < 8 || s.height > 1024)
    throw ParameterError(
        "size", fmt::format(" {}x{}: expected 8 to 1024 pixels a side", s.width, s.height));
  if (s.frames < 1 || s.frames > 1024)
    throw ParameterError("frames", fmt::format(" {}: expected 1 to 1024", s.frames));
  if (s.starts < 1 || s.starts > 10000)
    throw ParameterError("starts", fmt::format(" {}: expected 1 to 10000", s.starts));
  if (s.resamples < 0 || s.resamples > 100000)
    throw ParameterError("resamples", fmt::format(" {}: expected 0 to 100000", s.resamples));
  for (const std::string& a : s.acuities) make_acuity(a);
  make_filter(s.filter);
  for (const double p : s.norms) Metric(make_filter(s.filter), make_acuity(s.acuities[0]), p);
  for (const std::string& scene : s.scenes) frames_of(scene, 8, 8, 1);
  for (const std::string& p : s.perceptual) parse_perceptual(p);
}

std::vector<StudyObjective> study_objectives(const StudySettings& s) {
  std::vector<StudyObjective> out;
  for (const std::string& a : s.acuities)
    for (const double p : s.norms) out.push_back({s.filter, a, p, ""});
  for (const std::string& p : s.perceptual) out.push_back({"", "", 0, p});
  return out;
}

namespace {

// Every scene's frames and their references (from the cache when there is
// one). A 2x2 or 4x4 footprint reconstructs at the pixel corners (the
// renderer's Image::offset 1/2), so its references are rendered there too:
// `shifted`, when any pattern needs them. FLIP's half of each reference is
// prepared once, not once per pattern.
SceneFrames scene_frames(const StudySettings& s, const ReferenceSource& references,
                         const StudyProgress& progress, bool shifted = false) {
  SceneFrames out;
  for (size_t sc = 0; sc < s.scenes.size(); ++sc) {
    out.frames.push_back(frames_of(s.scenes[sc], s.width, s.height, s.frames));
    out.references.emplace_back();
    out.shifted.emplace_back();
    for (size_t f = 0; f < out.frames.back().size(); ++f) {
      ReferenceSettings ref = s.reference;
      ref.seed = frame_reference_seed(ref.seed, static_cast<int>(f));
      out.references.back().push_back(references(out.frames.back()[f], s.width, s.height, ref, 0));
      if (shifted)
        out.shifted.back().push_back(references(out.frames.back()[f], s.width, s.height, ref, 0.5));
    }
    out.flip_references.emplace_back();
    out.flip_shifted.emplace_back();
    for (const Image& r : out.references.back())
      out.flip_references.back().push_back(flip_reference(r));
    for (const Image& r : out.shifted.back()) out.flip_shifted.back().push_back(flip_reference(r));
    if (progress)
      progress(static_cast<int>(sc + 1), static_cast<int>(s.scenes.size()), "references");
  }
  return out;
}

// Each pattern's objectives, rendered measures (every pattern on every scene
// in parallel, each result in its own slot) and per-degree profile.
void measure(std::vector<StudyPattern>& patterns, const StudySettings& s,
             const std::vector<StudyObjective>& objectives, const SceneFrames& scenes) {
  // Per objective, its value of a pattern: E2 under its metric, or the
  // perceptual objective (its charts rendered once, here).
  std::vector<std::function<double(const Pattern&)>> objective_of;
  for (const StudyObjective& o : objectives) {
    if (o.perceptual.empty()) {
      const Metric metric(make_filter(o.filter), make_acuity(o.acuity), o.norm);
      objective_of.emplace_back([metric](const Pattern& p) { return metric.evaluate(p).e2; });
    } else {
      const auto perceptual =
          std::make_shared<const PerceptualObjective>(parse_perceptual(o.perceptual));
      objective_of.emplace_back([perceptual](const Pattern& p) { return (*perceptual)(p); });
    }
  }
  const Metric degree(make_filter(s.filter), make_acuity("uniform:step=1"));
  for (StudyPattern& p : patterns) p.measures.assign(s.scenes.size(), {});
  // Every (pattern, scene) is a work item (work/work_items.h).
  const size_t scene_count = s.scenes.size();
  const std::vector<std::string> results =
      run_work_items(static_cast<int>(patterns.size() * scene_count), [&](int task) {
        const size_t i = static_cast<size_t>(task) / scene_count,
                     sc = static_cast<size_t>(task) % scene_count;
        const bool corner = patterns[i].pattern.footprint.size != 1;
        if (corner && scenes.shifted[sc].empty())
          throw Error(
              fmt::format("study: {} reconstructs at pixel corners and no reference was "
                          "rendered there",
                          patterns[i].pattern.name));
        ByteWriter w;
        for (double m : render_measures(
                 patterns[i].pattern, scenes.frames[sc],
                 corner ? scenes.shifted[sc] : scenes.references[sc],
                 corner ? scenes.flip_shifted[sc] : scenes.flip_references[sc], s.width, s.height))
          w.put(m);
        return w.take();
      });
  for (size_t task = 0; task < results.size(); ++task) {
    ByteReader r(results[task]);
    for (double& m : patterns[task / scene_count].measures[task % scene_count]) m = r.get<double>();
    r.finish();
  }
  tbb::parallel_for(size_t{0}, patterns.size(), [&](size_t i) {
    StudyPattern& p = patterns[i];
    p.objective.clear();
    for (const auto& objective : objective_of) p.objective.push_back(objective(p.pattern));
    p.profile = degree.profile(make_kernel(p.pattern, 0));
  });
}

}  // namespace

std::vector<StudyPattern> measure_patterns(std::vector<StudyPattern> patterns,
                                           const StudySettings& s,
                                           const ReferenceSource& references) {
  validate(s);
  bool corner = false;
  for (const StudyPattern& p : patterns) corner = corner || p.pattern.footprint.size != 1;
  measure(patterns, s, study_objectives(s), scene_frames(s, references, {}, corner));
  return patterns;
}

RenderedObjective::RenderedObjective(const StudySettings& settings,
                                     const ReferenceSource& references, std::string measure,
                                     bool corner)
    : settings_(settings), measure_name_(std::move(measure)) {
  validate(settings_);
  const auto* it = std::find(kStudyMeasures.begin(), kStudyMeasures.end(), measure_name_);
  if (it == kStudyMeasures.end())
    throw ParameterError("measure", fmt::format(" '{}': expected one of {}", measure_name_,
                                                fmt::join(kStudyMeasures, ", ")));
  measure_ = static_cast<size_t>(it - kStudyMeasures.begin());
  scenes_ = std::make_shared<const SceneFrames>(scene_frames(settings_, references, {}, corner));
}

double RenderedObjective::operator()(const Pattern& p) const {
  const bool corner = p.footprint.size != 1;
  if (corner && scenes_->shifted[0].empty())
    throw Error(
        fmt::format("refine: {} reconstructs at pixel corners; its references must be "
                    "rendered there (corner)",
                    p.name));
  std::vector<double> per_scene(settings_.scenes.size());
  tbb::parallel_for(size_t{0}, per_scene.size(), [&](size_t sc) {
    per_scene[sc] = render_measures(
        p, scenes_->frames[sc], corner ? scenes_->shifted[sc] : scenes_->references[sc],
        corner ? scenes_->flip_shifted[sc] : scenes_->flip_references[sc], settings_.width,
        settings_.height)[measure_];
  });
  double sum = 0;
  for (const double v : per_scene) sum += v;
  return sum / static_cast<double>(per_scene.size());
}

std::string RenderedObjective::text() const {
  return fmt::format("{} over {} scenes at {}x{} (reference {} spp {})", measure_name_,
                     settings_.scenes.size(), settings_.width, settings_.height,
                     settings_.reference.samples, settings_.reference.filter);
}

std::vector<MeasureComparisons> compare_with_first(const std::vector<StudyPattern>& patterns,
                                                   const StudySettings& settings) {
  std::vector<MeasureComparisons> out;
  for (size_t k = 1; k < patterns.size(); ++k) {
    MeasureComparisons per;
    for (size_t q = 0; q < kStudyMeasures.size(); ++q) {
      std::vector<double> ours, theirs;
      for (size_t s = 0; s < patterns[k].measures.size(); ++s) {
        ours.push_back(patterns[k].measures[s][q]);
        theirs.push_back(patterns[0].measures[s][q]);
      }
      per[q] = compare_paired(ours, theirs, settings.resamples, 0.95, settings.seed);
    }
    out.push_back(per);
  }
  return out;
}

StudyResult objective_study(const StudySettings& s, const ReferenceSource& references,
                            const StudyProgress& progress) {
  validate(s);
  StudyResult r;
  r.objectives = study_objectives(s);
  for (size_t o = 0; o < r.objectives.size(); ++o)
    if (r.objectives[o].perceptual.empty() && r.objectives[o].acuity == "laine-aila" &&
        r.objectives[o].norm == Metric::kMaxNorm)
      r.papers = static_cast<int>(o);
  r.scenes = s.scenes;
  const SceneFrames scenes = scene_frames(s, references, progress);

  int done = 0;
  for (const int n : s.budgets) {
    BudgetStudy b;
    b.budget = n;
    if (progress)
      progress(done, static_cast<int>(s.budgets.size()), fmt::format("{} samples: optimizing", n));
    b.patterns = budget_patterns(s, r.objectives, n);
    const size_t count = b.patterns.size();
    measure(b.patterns, s, r.objectives, scenes);
    // The correlations, each with its own bootstrap seed from its place.
    b.correlations.resize(r.objectives.size() * s.scenes.size() * kStudyMeasures.size());
    tbb::parallel_for(size_t{0}, b.correlations.size(), [&](size_t c) {
      const size_t m = c % kStudyMeasures.size(),
                   sc = (c / kStudyMeasures.size()) % s.scenes.size(),
                   o = c / (kStudyMeasures.size() * s.scenes.size());
      std::vector<double> x(count), y(count);
      for (size_t i = 0; i < count; ++i) {
        x[i] = b.patterns[i].objective[o];
        y[i] = b.patterns[i].measures[sc][m];
      }
      b.correlations[c] = {static_cast<int>(o), static_cast<int>(sc), static_cast<int>(m),
                           rank_correlation(x, y, s.resamples, 0.95, s.seed * 1000003 + c)};
    });
    b.mean_spearman.assign(r.objectives.size(), 0.0);
    std::vector<int> counted(r.objectives.size(), 0);
    for (const StudyCorrelation& c : b.correlations)
      if (!std::isnan(c.r.spearman.value)) {
        b.mean_spearman[static_cast<size_t>(c.objective)] += c.r.spearman.value;
        ++counted[static_cast<size_t>(c.objective)];
      }
    for (size_t o = 0; o < r.objectives.size(); ++o) b.mean_spearman[o] /= std::max(1, counted[o]);
    r.budgets.push_back(std::move(b));
    if (progress)
      progress(++done, static_cast<int>(s.budgets.size()), fmt::format("{} samples", n));
  }
  r.mean_spearman.assign(r.objectives.size(), 0.0);
  for (const BudgetStudy& b : r.budgets)
    for (size_t o = 0; o < r.objectives.size(); ++o)
      r.mean_spearman[o] += b.mean_spearman[o] / double(r.budgets.size());
  r.recommended = static_cast<int>(
      std::max_element(r.mean_spearman.begin(), r.mean_spearman.end()) - r.mean_spearman.begin());
  return r;
}

std::vector<ObjectivePair> objective_pairs(const StudyResult& r, int measure, int resamples,
                                           uint64_t seed) {
  // Per objective and scene, rho averaged over the budgets that have it.
  const size_t scenes = r.scenes.size();
  std::vector<std::vector<double>> rho(r.objectives.size(), std::vector<double>(scenes, 0.0));
  std::vector<std::vector<int>> counted(r.objectives.size(), std::vector<int>(scenes, 0));
  for (const BudgetStudy& b : r.budgets)
    for (const StudyCorrelation& c : b.correlations)
      if (c.measure == measure && !std::isnan(c.r.spearman.value)) {
        rho[static_cast<size_t>(c.objective)][static_cast<size_t>(c.scene)] += c.r.spearman.value;
        ++counted[static_cast<size_t>(c.objective)][static_cast<size_t>(c.scene)];
      }
  // Scenes where some objective has no rho (a constant measure) are left out.
  std::vector<size_t> kept;
  for (size_t sc = 0; sc < scenes; ++sc) {
    bool all = true;
    for (size_t o = 0; o < r.objectives.size(); ++o) all = all && counted[o][sc] > 0;
    if (all) kept.push_back(sc);
  }
  std::vector<ObjectivePair> out;
  if (kept.empty()) return out;
  for (size_t a = 0; a < r.objectives.size(); ++a)
    for (size_t b = 0; b < r.objectives.size(); ++b) {
      if (a == b) continue;
      std::vector<double> ours, theirs;
      for (size_t sc : kept) {
        ours.push_back(rho[a][sc] / counted[a][sc]);
        theirs.push_back(rho[b][sc] / counted[b][sc]);
      }
      out.push_back({static_cast<int>(a), static_cast<int>(b),
                     compare_paired(ours, theirs, resamples, 0.95, seed)});
    }
  return out;
}

MeasureSpearman measure_spearman(const BudgetStudy& b, int objective, int measure) {
  double sum = 0, lo = INFINITY, hi = -INFINITY;
  int n = 0;
  for (const StudyCorrelation& c : b.correlations)
    if (c.objective == objective && c.measure == measure && !std::isnan(c.r.spearman.value)) {
      sum += c.r.spearman.value, ++n;
      lo = std::min(lo, c.r.spearman.low);
      hi = std::max(hi, c.r.spearman.high);
    }
  return {n ? sum / n : NAN, lo, hi};
}

}  // namespace aapat
