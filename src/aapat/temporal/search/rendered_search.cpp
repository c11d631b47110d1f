#include "aapat/temporal/search/rendered_search.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>

#include "aapat/optimize/compass_search.h"
#include "aapat/temporal/search/still_search.h"
#include "aapat/temporal/sequence/render_scale.h"
#include "aapat/temporal/sequence/sequence_json.h"

namespace aapat {

namespace {

// The comparison's motion, then the further ones.
std::vector<std::string> searched_motions(const RenderedSearch& s) {
  std::vector<std::string> out{s.comparison.motion};
  out.insert(out.end(), s.also_motions.begin(), s.also_motions.end());
  return out;
}

// Whether a frame's jitter is exactly the pixel centre.
bool has_null_jitter(const Sequence& s) {
  return std::any_of(s.frames.begin(), s.frames.end(),
                     [](const Pattern& f) { return f.sets[0][0].x == 0 && f.sets[0][0].y == 0; });
}

void check_jitter(const Sequence& s, const char* what) {
  validate(s);
  for (const Pattern& f : s.frames)
    if (f.footprint.size != 1 || f.set_count() != 1 || f.sets[0].size() != 1)
      throw Error(
          fmt::format("{} {}: a rendered search takes one-sample one-pixel frames", what, s.name));
}

}  // namespace

void validate(const RenderedSearch& s) {
  validate(s.comparison, 2);
  check_jitter(s.start, "start");
  check_jitter(s.baseline, "baseline");
  if (!(s.step > 0 && s.step <= 0.5))
    throw ParameterError("step", fmt::format(" {}: expected (0, 0.5] pixels", s.step));
  if (!(s.min_step > 0 && s.min_step <= s.step))
    throw ParameterError("min-step",
                         fmt::format(" {}: expected (0, step = {}]", s.min_step, s.step));
  if (!(s.loss >= 0 && s.loss <= 100))
    throw ParameterError("loss", fmt::format(" {}: expected 0 to 100", s.loss));
  if (!(s.jitter_bound >= kMinJitterBound && s.jitter_bound <= 0.5))
    throw ParameterError("jitter-bound", fmt::format(" {}: expected {} to 0.5 pixels",
                                                     s.jitter_bound, kMinJitterBound));
  const std::vector<std::string> motions = searched_motions(s);
  for (size_t i = 1; i < motions.size(); ++i) {
    EngineComparison c = s.comparison;
    c.motion = motions[i];
    validate(c, 2);
  }
  if (s.worst && std::none_of(motions.begin(), motions.end(), renders_several_ways))
    throw ParameterError("worst", fmt::format(": the motion {} renders each scene one way; "
                                              "a worst is taken after a cut or at the "
                                              "resonances",
                                              s.comparison.motion));
  if (s.comparison.taa.resolve == TaaResolve::fsr2_2 && has_null_jitter(s.start))
    throw ParameterError("start", fmt::format(" {}: a frame's jitter is (0, 0), which FSR 2 "
                                              "never takes (its sequence starts at index 1)",
                                              s.start.name));
  if (s.max_tries < 0)
    throw ParameterError("max-tries",
                         fmt::format(" {}: expected 0 (no limit) or more", s.max_tries));
}

RenderedSearchResult search_rendered(const RenderedSearch& s, const ReferenceSource& references,
                                     const ItemsProgress& progress) {
  validate(s);
  // One set of prepared scenes per motion searched, the baseline on each.
  struct Searched {
    PreparedScenes scenes;
    std::vector<ComparisonMeasures> base;
  };
  std::vector<Searched> searched;
  for (const std::string& motion : searched_motions(s)) {
    EngineComparison c = s.comparison;
    c.motion = motion;
    searched.push_back({PreparedScenes(c, references), {}});
  }
  // A sequence's measures on scene m: the mean over its ways, or the worst.
  const auto measures = [&](PreparedScenes& scenes, size_t m, const Sequence& q) {
    MeasureSpread spread;
    const ComparisonMeasures mean = scenes.render(m, q, s.comparison.taa, &spread);
    return s.worst && scenes.spread() ? spread.worst : mean;
  };
  for (Searched& one : searched)
    for (size_t m = 0; m < one.scenes.size(); ++m) {
      const ComparisonMeasures b = one.base.emplace_back(measures(one.scenes, m, s.baseline));
      if (!(b[0] > 0 && b[1] > 0 && b[2] > 0))
        throw Error(fmt::format(
            "the baseline {} has rmse {}, flicker {} and flip {} on {} ({}): a ratio cannot be "
            "taken; choose a motion or scenes where it errs and flickers",
            s.baseline.name, b[0], b[1], b[2], s.comparison.scenes[m], one.scenes.motion(m)));
    }
  Sequence trial = s.start;
  const bool null_refused = s.comparison.taa.resolve == TaaResolve::fsr2_2;
  // Inside the pixel ([-1/2, 1/2), as a sequence file holds it) and the bound.
  CompassSettings settings;
  settings.hi = std::min(s.jitter_bound, std::nextafter(0.5, 0.0));
  settings.lo = -s.jitter_bound;
  // The frames at x, centred when the sequence must be unbiased; false
  // where the centring leaves the bound.
  const auto place = [&](std::span<const double> x, Sequence& out) {
    const size_t n = out.frames.size();
    double mx = 0, my = 0;
    if (s.unbiased) {
      for (size_t f = 0; f < n; ++f) {
        mx += x[2 * f];
        my += x[2 * f + 1];
      }
      mx /= static_cast<double>(n);
      my /= static_cast<double>(n);
    }
    bool inside = true;
    for (size_t f = 0; f < n; ++f) {
      const Vec2 p{x[2 * f] - mx, x[2 * f + 1] - my};
      inside = inside && p.x >= settings.lo && p.x <= settings.hi && p.y >= settings.lo &&
               p.y <= settings.hi;
      out.frames[f].sets[0][0] = p;
    }
    return inside;
  };
  const auto objective = [&](std::span<const double> x) {
    if (!place(x, trial)) return HUGE_VAL;
    if (null_refused && has_null_jitter(trial)) return HUGE_VAL;  // never a null vector
    double total = 0;
    for (Searched& one : searched) {
      double sum = 0;
      for (size_t m = 0; m < one.scenes.size(); ++m) {
        const ComparisonMeasures v = measures(one.scenes, m, trial);
        const ComparisonMeasures& b = one.base[m];
        const double a = std::log(v[0] / b[0]), e = std::log(v[1] / b[1]),
                     c = std::log(v[2] / b[2]);
        sum += a + c + s.loss * (std::max(0.0, a) + std::max(0.0, c)) +
               (1 + s.loss) * std::max(0.0, e);
      }
      total += sum / static_cast<double>(one.scenes.size());
    }
    return total / static_cast<double>(searched.size());
  };
  FunctionObjective f(objective, 2);
  settings.step = s.step;
  settings.min_step = s.min_step;
  settings.max_tries = s.max_tries;
  std::vector<double> x;
  for (const Pattern& p : s.start.frames)
    x.insert(x.end(), {std::clamp(p.sets[0][0].x, settings.lo, settings.hi),
                       std::clamp(p.sets[0][0].y, settings.lo, settings.hi)});
  // An unbiased search starts from the start centred, which must stay in bounds.
  Sequence centred = s.start;
  if (!place(x, centred))
    throw ParameterError("start", fmt::format(" {}: centred to a mean jitter of (0, 0) (unbiased), "
                                              "a frame leaves +-{} pixels",
                                              s.start.name, s.jitter_bound));
  for (size_t f = 0; f < centred.frames.size(); ++f) {
    x[2 * f] = centred.frames[f].sets[0][0].x;
    x[2 * f + 1] = centred.frames[f].sets[0][0].y;
  }
  // Each value is rendered afresh (no incremental sums): any lower value is a gain.
  settings.min_gain = 0;
  const CompassResult found = compass_search(f, std::move(x), settings, progress);
  RenderedSearchResult r;
  r.start_value = found.start_value;
  r.value = found.value;
  r.tries = found.tries;
  r.kept = found.kept;
  r.best = s.start;
  place(found.x, r.best);
  r.best.name = fmt::format("rendered-search-{}", r.best.period());
  r.best.description = fmt::format(
      "{} frames of 1 sample searched on rendered error under {} at {:g}x against {}: the mean "
      "log ratio of rmse and flip, flicker not above, over {} scenes ({}{}), losses weighted "
      "{}{}",
      r.best.period(), s.comparison.taa.preset, s.comparison.taa.upscale.ratio, s.baseline.name,
      s.comparison.scenes.size(), fmt::join(searched_motions(s), " + "),
      s.worst ? ", each scene's worst" : "", 1 + s.loss, s.unbiased ? "; unbiased (mean 0)" : "");
  r.best.provenance = {{"optimizer", "aapat sequence search (compass search on rendered error)"},
                       {"taa", s.comparison.taa.preset},
                       {"taa_settings", engine_taa_text(s.comparison.taa)},
                       {"ratio", fmt::format("{:g}", s.comparison.taa.upscale.ratio)},
                       {"against", s.baseline.name},
                       {"from", s.start.name},
                       {"scenes", std::to_string(s.comparison.scenes.size())},
                       {"motion", fmt::format("{}", fmt::join(searched_motions(s), " + "))},
                       {"seed", std::to_string(s.comparison.seed)},
                       {"loss", fmt::format("{:g}", s.loss)},
                       {"worst", s.worst ? "1" : "0"},
                       {"unbiased", s.unbiased ? "1" : "0"},
                       {"start_value", fmt::format("{:.6f}", r.start_value)},
                       {"value", fmt::format("{:.6f}", r.value)}};
  if (s.comparison.taa.upscale.ratio > 1) {
    std::string warning =
        upscaler_rule_warning(r.best.name, r.best.period(), s.comparison.taa.upscale.ratio);
    if (!warning.empty()) r.warnings.push_back(std::move(warning));
  }
  return r;
}

JsonObject rendered_search_json(const RenderedSearch& s, const RenderedSearchResult& r) {
  JsonObject doc = json_report("sequence search");
  const EngineComparison& c = s.comparison;
  doc.update(comparison_settings_json(c));
  doc.update(JsonObject{{"scenes", c.scenes},
                        {"against", s.baseline.name},
                        {"from", s.start.name},
                        {"step", s.step},
                        {"min_step", s.min_step},
                        {"loss", s.loss},
                        {"worst", s.worst},
                        {"unbiased", s.unbiased},
                        {"motions", searched_motions(s)},
                        {"jitter_bound", s.jitter_bound},
                        {"start_value", r.start_value},
                        {"value", r.value},
                        {"tries", r.tries},
                        {"kept", r.kept}});
  doc["result"] = JsonObject::parse(sequence_to_json(r.best));
  return doc;
}

}  // namespace aapat
