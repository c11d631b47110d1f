// The steepest-descent heuristic of Laine & Aila Sec. 5.2: every
// (kernel, angle) term pulls the pattern down its own gradient, the terms
// within t of the current E2 with the large step c1 = ratio * c0 and the
// rest with c0, so that all near-maximal terms fall together instead of the
// iteration oscillating between them. The step c0 grows after a step that
// lowers E2 and halves (the step retried) after one that does not, so E2
// never ends worse than it started.
#pragma once

#include "aapat/optimize/problem_e2.h"
#include "aapat/optimize/settings.h"

namespace aapat {

// With Method::kMinimax the direction is the eps-active minimum-norm one
// (ProblemE2::minimax_direction) and a step is taken only where it lowers E2.
RunResult descend(const ProblemE2& objective, Problem& problem, const OptimizerSettings& settings);

// The weights alone, positions held (Laine-Aila's "Opt W"): the heuristic,
// then the minimax polish. E1^2 is quadratic in the weights, so this is a
// convex problem and the result is its optimum to the descent's tolerance.
double optimize_weights(const ProblemE2& objective, Problem& problem,
                        const OptimizerSettings& settings);
// The pattern with its weights optimized, positions as they are.
Pattern with_optimized_weights(const Metric& metric, const Pattern& p, bool nonnegative);

}  // namespace aapat
