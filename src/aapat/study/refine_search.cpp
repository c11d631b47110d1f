#include "aapat/study/refine_search.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/hardware_layout.h"
#include "aapat/core/interrupt.h"
#include "aapat/core/lattice.h"
#include "aapat/core/metric.h"
#include "aapat/core/objective.h"
#include "aapat/io/json_report.h"
#include "aapat/optimize/compass_search.h"
#include "aapat/optimize/problem.h"

namespace aapat {
namespace {

// Where each search coordinate goes: a generator's x or y, or a weight.
struct Coordinate {
  enum Kind { kX, kY, kWeight } kind;
  int index;
};

std::vector<Coordinate> coordinates(const Problem& p) {
  std::vector<Coordinate> out;
  for (size_t g = 0; g < p.generators.size(); ++g) {
    const Freedom f = p.generators[g].freedom;
    if (f == Freedom::kFree || f == Freedom::kSlideX) out.push_back({Coordinate::kX, int(g)});
    if (f == Freedom::kFree || f == Freedom::kSlideY) out.push_back({Coordinate::kY, int(g)});
  }
  for (const auto& group : p.weight_groups)
    if (group.size() > 1)
      for (int w : group) out.push_back({Coordinate::kWeight, w});
  return out;
}

// The problem moved by x (displacements from the start), on its constraints.
Problem moved(const Problem& start, const std::vector<Coordinate>& coords,
              std::span<const double> x) {
  Problem p = start;
  for (size_t k = 0; k < coords.size(); ++k) {
    const Coordinate& c = coords[k];
    if (c.kind == Coordinate::kX) p.generators[c.index].pos.x += x[k];
    if (c.kind == Coordinate::kY) p.generators[c.index].pos.y += x[k];
    if (c.kind == Coordinate::kWeight) p.weights[c.index] += x[k];
  }
  project_to_constraints(p, true);
  return p;
}

// d value / d problem.weights from d value / d Pattern::weights: a weight
// variable read by several kernels (a mirrored tile's) gathers each read's.
std::vector<double> problem_weight_gradient(const Problem& p,
                                            const std::vector<std::vector<double>>& pattern_grad) {
  std::vector<double> g(p.weights.size(), 0.0);
  for (size_t k = 0; k < p.kernels.size(); ++k)
    for (size_t r = 0; r < p.kernels[k].size(); ++r)
      g[static_cast<size_t>(p.kernels[k][r].weight)] += pattern_grad[k][r];
  return g;
}

// Projected gradient descent on the weights, the positions held: the
// gradient's component within each group's plane (sum 1), scaled so that
// the largest weight moves `step`, the result projected onto the
// constraints; a step that does not lower the value is halved, down to
// min_step, and the search ends there or after `steps` steps.
struct WeightDescent {
  Problem problem;
  double value = 0;
  int steps = 0, evaluations = 0;
};
WeightDescent descend_weights(Problem problem, double value, const RefineObjective& objective,
                              const RefineSettings& s,
                              const std::function<Pattern(const Problem&)>& pattern) {
  WeightDescent d{problem, value, 0, 0};
  double step = s.step;
  while (d.steps < s.weight_steps && step >= s.min_step) {
    throw_if_interrupted();
    std::vector<double> g =
        problem_weight_gradient(d.problem, objective.weight_gradient(pattern(d.problem)));
    ++d.evaluations;
    double largest = 0;
    for (const auto& group : d.problem.weight_groups) {
      double mean = 0;
      for (int w : group) mean += g[static_cast<size_t>(w)];
      mean /= static_cast<double>(group.size());
      for (int w : group) {
        g[static_cast<size_t>(w)] = group.size() > 1 ? g[static_cast<size_t>(w)] - mean : 0;
        largest = std::max(largest, std::abs(g[static_cast<size_t>(w)]));
      }
    }
    if (largest == 0) break;
    bool lowered = false;
    while (step >= s.min_step) {
      Problem next = d.problem;
      for (size_t w = 0; w < g.size(); ++w) next.weights[w] -= step / largest * g[w];
      project_to_constraints(next, true);
      const double v = objective.value(pattern(next));
      ++d.evaluations;
      if (v < d.value) {
        d.problem = std::move(next), d.value = v, lowered = true;
        break;
      }
      step /= 2;
    }
    if (!lowered) break;
    ++d.steps;
  }
  return d;
}

}  // namespace

RefineObjective refine_objective(const PerceptualObjective& objective) {
  return {[&objective](const Pattern& p) { return objective(p); }, objective.spec().text(),
          "perceptual", [&objective](const Pattern& p) { return objective.gradient(p).weights; }};
}

RefineObjective refine_objective(const RenderedObjective& objective) {
  return {
      [&objective](const Pattern& p) { return objective(p); }, objective.text(), "rendered", {}};
}

void validate(const RefineSettings& s, const Pattern& start) {
  if (!(s.step > 0 && s.step <= 1))
    throw ParameterError("step", fmt::format(" {}: expected (0, 1] pixels", s.step));
  if (!(s.min_step > 0 && s.min_step <= s.step))
    throw ParameterError("min-step", fmt::format(" {}: expected (0, step]", s.min_step));
  if (s.max_tries < 1 || s.max_tries > 10'000'000)
    throw ParameterError("max-tries", fmt::format(" {}: expected 1 to 10^7", s.max_tries));
  if (s.weight_steps < 0 || s.weight_steps > kMaxWeightSteps)
    throw ParameterError("weight-steps",
                         fmt::format(" {}: expected 0 to {}", s.weight_steps, kMaxWeightSteps));
  if (!s.api.empty()) {
    const ApiProfile& profile = api_profile(s.api);
    hardware_layout(snap_to_lattice(start, kLatticeSteps, profile.y_down), profile);
  }
}

RefineResult refine_pattern(const Pattern& original, const RefineObjective& objective,
                            const RefineSettings& s, const ItemsProgress& progress) {
  validate(s, original);
  if (s.weight_steps > 0 && !objective.weight_gradient)
    throw ParameterError("weight-steps", fmt::format(": the objective {} has no weight gradient "
                                                     "(the perceptual objective has)",
                                                     objective.text));
  const ApiProfile* profile = s.api.empty() ? nullptr : &api_profile(s.api);
  // On an API's lattice every candidate is measured snapped: the search's
  // positions move in continuous steps, but only a step that carries a
  // sample to another lattice point changes the value.
  const auto on_target = [&](const Pattern& p) {
    if (!profile) return p;
    Pattern q = snap_to_lattice(p, kLatticeSteps, profile->y_down);
    if (!q.footprint.plus) {
      // A one-pixel pattern's samples stay strictly inside, as optimize's
      // lattice search keeps them.
      const double inside = strictly_inside_bound(kLatticeSteps);
      for (auto& set : q.sets)
        for (Vec2& v : set)
          v = {std::clamp(v.x, -inside, inside), std::clamp(v.y, -inside, inside)};
      validate(q);  // two samples clamped onto one point
    }
    return q;
  };
  const Pattern start = on_target(original);
  Problem problem = problem_from_pattern(start);
  // The catalog's one-pixel patterns keep their samples strictly inside (an
  // MSAA sample on the border would be its neighbour's).
  if (!start.footprint.plus) keep_strictly_inside(problem);
  project_to_constraints(problem, true);
  const std::vector<Coordinate> coords = coordinates(problem);
  const auto candidate = [&](std::span<const double> x) {
    return on_target(pattern_of(moved(problem, coords, x)));
  };
  // Two samples snapped onto one lattice point make no pattern: no candidate.
  FunctionObjective f(
      [&](std::span<const double> x) {
        if (!profile) return objective.value(candidate(x));
        Pattern p;
        try {
          p = candidate(x);
        } catch (const Error&) {
          return std::numeric_limits<double>::infinity();
        }
        return objective.value(p);
      },
      1);
  CompassSettings cs;
  cs.block_size = 1;
  cs.step = s.step;
  cs.min_step = s.min_step;
  cs.lo = -1, cs.hi = 1;
  cs.max_tries = s.max_tries;
  const CompassResult r = compass_search(f, std::vector<double>(coords.size(), 0.0), cs, progress);
  // The search starts from the start put on the constraints (weights made
  // non-negative, samples inside); where that alone made it worse, the start
  // itself is the answer. Either way the result records what was searched.
  const double first = objective.value(start);
  int tries = r.tries;
  Problem searched = moved(problem, coords, r.x);
  double value = r.value;
  const double compass_value = r.value;
  int gradient_steps = 0;
  if (s.weight_steps > 0) {
    const WeightDescent d = descend_weights(
        searched, value, objective, s, [&](const Problem& p) { return on_target(pattern_of(p)); });
    searched = d.problem, value = d.value, gradient_steps = d.steps;
    tries += d.evaluations;
  }
  const bool improved = value < first;
  Pattern best = improved ? on_target(pattern_of(searched)) : start;
  if (!improved) value = first;
  // A new name: a file named like the catalog entry with other samples would
  // be read under its file's name, with a warning (io/catalog_clash.h).
  best.name = original.name + "-" + objective.key;
  best.description = original.description + ", refined under the " +
                     (objective.key == "perceptual" ? std::string("perceptual objective")
                                                    : "mean " + objective.text);
  // The provenance's E2 (the search's record, which `aapat list` shows) is
  // the refined pattern's under the objective the start was designed for;
  // a start designed for none (a published pattern) records where it came
  // from and its E2 under the default objective, named in full.
  best.provenance = original.provenance;
  const std::optional<Objective> designed = design_objective(original);
  const Objective recorded = designed ? *designed : named_objective(kDefaultObjective);
  const std::string e2 = fmt::format("{:.6f}", recorded.metric().evaluate(best).e2);
  if (designed) {
    for (auto& [key, value] : best.provenance)
      if (key == "e2" || key == "lattice_e2") value = e2;
  } else {
    best.provenance = {{"refined_from", original.name}, {"filter", recorded.filter},
                       {"acuity", recorded.acuity},     {"norm", format_norm(recorded.norm)},
                       {"objective", recorded.text()},  {"e2", e2}};
  }
  if (profile) {  // where the start was free, the lattice and its E2 as optimize records them
    bool noted = false;
    for (const auto& [key, value] : best.provenance) noted = noted || key == "api";
    if (!noted) {
      std::erase_if(best.provenance, [](const auto& kv) { return kv.first == "lattice"; });
      best.provenance.emplace_back("lattice", fmt::format("1/{} pixel", kLatticeSteps));
      best.provenance.emplace_back("api", profile->name);
      best.provenance.emplace_back("lattice_e2", e2);
    }
  }
  // A pattern refined twice (the catalog's charts, then content) records the
  // last objective; the first's value stays under its own key.
  std::erase_if(best.provenance,
                [&](const auto& kv) { return kv.first == "refined" || kv.first == objective.key; });
  best.provenance.emplace_back("refined", objective.text);
  best.provenance.emplace_back(objective.key, fmt::format("{:.6f}", value));
  return {best, first, value, tries, compass_value, gradient_steps};
}

nlohmann::ordered_json refine_json(const RefineObjective& objective, const Pattern& start,
                                   const RefineSettings& settings, const RefineResult& result) {
  JsonObject doc = json_report("refine");
  doc.update(JsonObject{
      {"objective", objective.text}, {"pattern", start.name}, {"family", family(start)}});
  if (!settings.api.empty()) doc["api"] = settings.api;
  doc.update(
      JsonObject{{"before", result.start_value}, {"after", result.value}, {"tries", result.tries}});
  if (settings.weight_steps > 0)
    doc.update(JsonObject{{"compass_after", result.compass_value},
                          {"weight_steps", result.gradient_steps}});
  return doc;
}

}  // namespace aapat
