#include "aapat/optimize/descent.h"

#include "aapat/optimize/epigraph.h"

#include <algorithm>
#include <cmath>

namespace aapat {
namespace {

void step(const Problem& from, const Direction& dir, double c0, bool nonnegative, Problem& to) {
  for (size_t g = 0; g < from.generators.size(); ++g)
    to.generators[g].pos = from.generators[g].pos - c0 * dir.pos[g];
  for (size_t i = 0; i < from.weights.size(); ++i) to.weights[i] = from.weights[i] - c0 * dir.w[i];
  project_to_constraints(to, nonnegative);
}

}  // namespace

RunResult descend(const ProblemE2& objective, Problem& problem, const OptimizerSettings& s) {
  if (is_epigraph(s.method))
    return epigraph(objective, problem, s,
                    s.method == Method::kSlsqp ? EpigraphAlgorithm::slsqp
                    : s.method == Method::kMma ? EpigraphAlgorithm::mma
                                               : EpigraphAlgorithm::ccsaq);
  Workspace ws;
  Direction dir;
  RunResult r = begin_run(objective, problem, s.nonnegative_weights, ws);
  // Positions that stay put: their per-angle tables once (held_positions.h).
  if (s.weights_only) ws.held.hold(objective.metric(), ws.kernels);
  double e2 = r.initial_e2;
  Problem trial = problem, best = problem;
  double best_e2 = e2, window_start = e2;
  double c0 = s.initial_step;
  double eps = 1 - s.threshold;  // minimax: the active set's width, relative to E2
  for (r.iterations = 0; r.iterations < s.max_iterations && !past(s); ++r.iterations) {
    if (s.method == Method::kMinimax) {
      objective.minimax_direction(problem, ws, e2, 1 - eps, !s.weights_only, dir);
      // Monotone: halve the step until E2 falls.
      bool improved = false;
      for (; c0 >= s.min_step && !improved; c0 *= 0.5) {
        step(problem, dir, c0, s.nonnegative_weights, trial);
        const double next = objective.e2(trial, ws);
        ++r.evaluations;
        if (next < e2) {
          std::swap(problem, trial);
          e2 = best_e2 = next;
          best.generators = problem.generators;
          best.weights = problem.weights;
          improved = true;
          c0 *= 4;  // net growth 2 after the loop's halving
        }
      }
      if (!improved) {
        // No descent for this active set: narrow it to the terms nearer the
        // maximum and try again from the same point.
        eps *= 0.1;
        c0 = s.initial_step;
        if (eps < 1e-9) break;
        continue;
      }
      eps = std::min(1 - s.threshold, eps * 2);
      if ((r.iterations + 1) % s.window == 0) {
        if (window_start - best_e2 < s.tolerance * window_start) break;
        window_start = best_e2;
      }
      continue;
    }
    objective.heuristic_direction(problem, ws, e2, s.threshold, s.step_ratio, !s.weights_only, dir);
    step(problem, dir, c0, s.nonnegative_weights, trial);
    const double next = objective.e2(trial, ws);
    ++r.evaluations;
    if (!std::isfinite(next)) break;  // a step the arithmetic cannot follow: keep the best point
    // Take the step either way (near a kink of the maximum the iteration
    // zig-zags down), but grow c0 after a gain and shrink it after a loss.
    std::swap(problem, trial);
    c0 *= next < e2 ? 1.05 : 0.8;
    e2 = next;
    if (e2 < best_e2) {
      best_e2 = e2;
      best.generators = problem.generators;
      best.weights = problem.weights;
    }
    if (c0 < s.min_step) break;
    if ((r.iterations + 1) % s.window == 0) {
      if (window_start - best_e2 < s.tolerance * window_start) break;
      window_start = best_e2;
    }
  }
  problem = std::move(best);
  r.final_e2 = best_e2;  // E2 never ends worse than it started
  return r;
}

double optimize_weights(const ProblemE2& objective, Problem& problem,
                        const OptimizerSettings& settings) {
  OptimizerSettings s = settings;
  s.weights_only = true;
  s.deadline.reset();
  s.method = Method::kDescent;
  descend(objective, problem, s);
  s.method = Method::kMinimax;
  return descend(objective, problem, s).final_e2;
}

Pattern with_optimized_weights(const Metric& metric, const Pattern& p, bool nonnegative) {
  Problem problem = problem_from_pattern(p);
  OptimizerSettings s;
  s.nonnegative_weights = nonnegative;
  optimize_weights(ProblemE2(metric), problem, s);
  Pattern q = pattern_of(problem);
  q.name = p.name;
  q.description = p.description;
  q.provenance = p.provenance;
  q.provenance.emplace_back("weights", nonnegative ? "optimized, non-negative" : "optimized");
  return q;
}

}  // namespace aapat
