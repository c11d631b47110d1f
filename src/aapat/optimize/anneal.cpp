#include "aapat/optimize/anneal.h"
#include "aapat/generate/portable_random.h"

#include <cmath>

namespace aapat {

RunResult anneal(const ProblemE2& objective, Problem& problem, const OptimizerSettings& s,
                 std::mt19937_64& rng) {
  Workspace ws;
  RunResult r = begin_run(objective, problem, s.nonnegative_weights, ws);
  double e2 = r.initial_e2;
  Problem trial = problem, best = problem;
  double best_e2 = e2;
  const auto u = [](std::mt19937_64& r) { return unit_double(r); };
  Gaussian gauss;
  // The descent spends about three evaluations an iteration: give annealing
  // the same number of evaluations.
  const int steps = 3 * s.max_iterations;
  const double t0 = 0.02 * e2;
  // The schedule's and the acceptance's exponentials with aapat's own exp,
  // the same on every platform; its fast form, as every step takes three.
  const double log_cool = portable_log(1e-4), log_shrink = portable_log(1e-3);
  for (r.iterations = 0; r.iterations < steps && !past(s); ++r.iterations) {
    const double progress = static_cast<double>(r.iterations) / steps;
    const double temperature = t0 * portable_exp_fast(progress * log_cool);
    const double scale = 0.05 * portable_exp_fast(progress * log_shrink);
    trial.generators = problem.generators;
    trial.weights = problem.weights;
    const bool move_weight = s.weights_only || u(rng) < 0.5;
    if (!move_weight) {
      Generator& g = trial.generators[rng() % trial.generators.size()];
      if (g.freedom == Freedom::kFree || g.freedom == Freedom::kSlideX)
        g.pos.x += scale * gauss(rng);
      if (g.freedom == Freedom::kFree || g.freedom == Freedom::kSlideY)
        g.pos.y += scale * gauss(rng);
    } else {
      // Move weight from one sample to another: the group's sum stays 1.
      const auto& group = trial.weight_groups[rng() % trial.weight_groups.size()];
      const int a = group[rng() % group.size()], b = group[rng() % group.size()];
      const double d = 0.2 * scale * gauss(rng);
      trial.weights[a] += d;
      trial.weights[b] -= d;
    }
    project_to_constraints(trial, s.nonnegative_weights);
    const double next = objective.e2(trial, ws);
    ++r.evaluations;
    if (next < e2 || u(rng) < portable_exp_fast(-(next - e2) / temperature)) {
      std::swap(problem, trial);
      e2 = next;
      if (e2 < best_e2) {
        best_e2 = e2;
        best = problem;
      }
    }
  }
  problem = best;
  r.final_e2 = best_e2;
  return r;
}

}  // namespace aapat
