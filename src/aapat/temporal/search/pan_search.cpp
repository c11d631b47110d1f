#include "aapat/temporal/search/pan_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "aapat/optimize/compass_search.h"
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
  // The objective sees the samples where the preset places them (centre
  // plus jitter_sign x jitter): the search moves those, within the bounds
  // mirrored with them.
  const double sign = search.taa.jitter_sign;
  for (const Pattern& f : search.start.frames)
    jitter.push_back(
        {sign * std::clamp(f.sets[0][0].x, lo, hi), sign * std::clamp(f.sets[0][0].y, lo, hi)});
  // The pan objective under the generic compass search: a frame's x and y
  // are one block, moved incrementally (pan_objective.h).
  class Adapter final : public CompassObjective {
   public:
    explicit Adapter(PanObjective& o) : o_(o) {}
    std::vector<double> start_values;
    double set(std::span<const double> x) override {
      std::vector<Vec2> j(x.size() / 2);
      for (size_t f = 0; f < j.size(); ++f) j[f] = {x[2 * f], x[2 * f + 1]};
      o_.set(j);
      if (start_values.empty()) start_values = o_.case_values();
      return o_.value();
    }
    double try_move(size_t block, std::span<const double> to) override {
      return o_.try_move(static_cast<int>(block), {to[0], to[1]});
    }
    void move(size_t block, std::span<const double> to) override {
      o_.move(static_cast<int>(block), {to[0], to[1]});
    }

   private:
    PanObjective& o_;
  } adapter(objective);
  std::vector<double> x;
  for (const Vec2 j : jitter) x.insert(x.end(), {j.x, j.y});
  CompassSettings settings;
  settings.step = search.step;
  settings.min_step = search.min_step;
  settings.lo = sign > 0 ? lo : -hi;
  settings.hi = sign > 0 ? hi : -lo;
  settings.max_sweeps = kMaxPanSweeps;
  const CompassResult found = compass_search(adapter, std::move(x), settings, progress);
  r.start_values = adapter.start_values;
  r.start_value = found.start_value;
  r.tries = found.tries;
  r.kept = found.kept;
  r.values = objective.case_values();
  r.value = objective.value();
  r.best = search.start;
  for (size_t f = 0; f < r.best.frames.size(); ++f)
    r.best.frames[f].sets[0][0] = {sign * objective.jitter()[f].x, sign * objective.jitter()[f].y};
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
