#include "aapat/temporal/search/pan_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/temporal/engine/engine_pans.h"
#include "aapat/temporal/model/pan_model.h"
#include "aapat/temporal/search/pan_objective.h"
#include "aapat/temporal/search/still_search.h"
#include "aapat/temporal/sequence/sequence_json.h"

namespace aapat {

Sequence pan_search_start(int frames, const std::string& from) {
  if (frames < 1 || frames > kMaxPanFrames)
    throw ParameterError("sequence", fmt::format(" {}: a pan's evaluation takes 1 to {} frames",
                                                 frames, kMaxPanFrames));
  Sequence s = resolve_sequence(from.empty() ? fmt::format("halton:frames={}", frames) : from);
  if (s.period() != frames)
    throw ParameterError("from", fmt::format(" {}: {} frames, not {}", s.name, s.period(), frames));
  return s;
}

void validate(const PanSequenceSearch& s) {
  validate(s.start);
  if (s.start.frames[0].footprint.size != 1 || s.start.frames[0].set_count() != 1 ||
      s.start.frames[0].sets[0].size() != 1)
    throw ParameterError(
        "from", fmt::format(" {}: a pan search moves one-sample one-pixel frames", s.start.name));
  if (s.start.period() > kMaxPanFrames)
    throw ParameterError("sequence", fmt::format(" {}: a pan's evaluation takes at most {} frames",
                                                 s.start.period(), kMaxPanFrames));
  if (!(s.step > 0 && s.step <= 0.5))  // NaN fails too
    throw ParameterError("step", fmt::format(" {}: expected (0, 0.5] pixels", s.step));
  if (!(s.min_step > 0 && s.min_step <= s.step))
    throw ParameterError("min-step",
                         fmt::format(" {}: expected (0, step = {}]", s.min_step, s.step));
  if (!(s.jitter_bound >= kMinJitterBound && s.jitter_bound <= 0.5))
    throw ParameterError("jitter-bound", fmt::format(" {}: expected {} to 0.5 pixels",
                                                     s.jitter_bound, kMinJitterBound));
  for (const Vec2 v : s.velocities) check_velocity(v);
  check_ratio(s.taa.upscale.ratio);
}

PanSequenceSearchResult search_sequence_under_pans(const PanSequenceSearch& search,
                                                   const Metric& metric,
                                                   const ItemsProgress& progress) {
  validate(search);
  PanSequenceSearchResult r;
  r.velocities = search.velocities.empty() ? default_pan_velocities() : search.velocities;
  std::vector<PanCase> cases;
  for (const Vec2 v : r.velocities)
    cases.push_back({pan_model_of(search.taa, v), steady_alpha(search.taa, v.x != 0 || v.y != 0)});
  PanObjective objective(search.start.period(), cases, metric);
  std::vector<Vec2> jitter;
  // Inside the pixel ([-1/2, 1/2), as a sequence file holds it) and the bound.
  const double hi = std::min(search.jitter_bound, std::nextafter(0.5, 0.0)),
               lo = -search.jitter_bound;
  for (const Pattern& f : search.start.frames)
    jitter.push_back({std::clamp(f.sets[0][0].x, lo, hi), std::clamp(f.sets[0][0].y, lo, hi)});
  objective.set(jitter);
  r.start_values = objective.case_values();
  r.start_value = objective.value();
  double best = r.start_value;
  const int levels =
      1 + static_cast<int>(std::floor(std::log2(search.step / search.min_step) + 1e-9));
  double step = search.step;
  for (int level = 0; level < levels; ++level, step /= 2) {
    for (int sweep = 0, kept_any = 1; kept_any && sweep < kMaxPanSweeps; ++sweep) {
      kept_any = 0;
      for (int f = 0; f < search.start.period(); ++f) {
        const Vec2 at = objective.jitter()[static_cast<size_t>(f)];
        for (const Vec2 d : {Vec2{step, 0}, Vec2{-step, 0}, Vec2{0, step}, Vec2{0, -step}}) {
          const Vec2 to{at.x + d.x, at.y + d.y};
          if (to.x < lo || to.x > hi || to.y < lo || to.y > hi) continue;
          ++r.tries;
          const double v = objective.try_move(f, to);
          if (v < best * (1 - 1e-12)) {
            objective.move(f, to);
            best = v;
            ++r.kept;
            kept_any = 1;
            break;
          }
        }
      }
      // Rebuilt from scratch once a sweep: what the moves' sums drifted.
      objective.set(objective.jitter());
      best = objective.value();
      if (progress && kept_any)
        progress(level, levels,
                 fmt::format("J {:.6f} at step {:g}, sweep {}", best, step, sweep + 1));
    }
    if (progress) progress(level + 1, levels, fmt::format("J {:.6f} at step {:g}", best, step));
  }
  r.values = objective.case_values();
  r.value = objective.value();
  r.best = search.start;
  for (size_t f = 0; f < r.best.frames.size(); ++f)
    r.best.frames[f].sets[0][0] = objective.jitter()[f];
  r.best.name = fmt::format("pan-search-{}", search.start.period());
  if (search.taa.upscale.ratio > 1) {
    std::string warning =
        upscaler_rule_warning(r.best.name, search.start.period(), search.taa.upscale.ratio);
    if (!warning.empty()) r.warnings.push_back(std::move(warning));
  }
  r.best.description = fmt::format(
      "{} frames of 1 sample optimized for the pan model's steady mean E2 under {} at {:g}x, the "
      "mean over {} velocities",
      search.start.period(), search.taa.preset, search.taa.upscale.ratio, r.velocities.size());
  std::string velocities;
  for (const Vec2 v : r.velocities)
    velocities += fmt::format("{}{:g},{:g}", velocities.empty() ? "" : " ", v.x, v.y);
  r.best.provenance = {
      {"optimizer", "aapat optimize --sequence --taa (compass search on the pan model)"},
      {"frames", std::to_string(search.start.period())},
      {"taa", search.taa.preset},
      {"taa_settings", engine_taa_text(search.taa)},
      {"ratio", fmt::format("{:g}", search.taa.upscale.ratio)},
      {"velocities", velocities},
      {"from", search.start.name},
      {"step", fmt::format("{:g}", search.step)},
      {"min_step", fmt::format("{:g}", search.min_step)},
      {"filter", metric.filter().name()},
      {"acuity", metric.acuity().name},
      {"norm", format_norm(metric.norm())},
      {"start_mean_e2", fmt::format("{:.6f}", r.start_value)},
      {"mean_e2", fmt::format("{:.6f}", r.value)}};
  if (search.jitter_bound < 0.5)
    r.best.provenance.emplace_back("jitter_bound", fmt::format("{}", search.jitter_bound));
  validate(r.best);
  return r;
}

}  // namespace aapat
