// E2 minimized in its epigraph form with NLopt's constrained gradient
// methods: minimize s over the pattern's free parameters and s, subject to
// W(theta)^2 E1_k(theta)^2 <= s for every kernel k and angle theta of the
// table. The maximum that makes E2 non-smooth becomes a set of smooth
// constraints, each with the metric's analytic gradient, so a
// sequential-quadratic method (SLSQP) or a conservative convex one (MMA,
// CCSA with quadratic approximations) can move all the active terms down at
// once, where the descent heuristic and the minimax step stall at the kinks.
//
// The parameters: each generator's free coordinates (bounded by its limit),
// each weight group's weights but its last (the last is 1 - the others;
// with non-negative weights every weight is kept >= 0), and s. Only the
// maximum over angles (--norm inf) has this form.
#pragma once

#include <string_view>

#include "aapat/optimize/problem_e2.h"

namespace aapat {

// NLopt's LD_SLSQP, LD_MMA, LD_CCSAQ.
enum class EpigraphAlgorithm { slsqp, mma, ccsaq };

// Minimizes E2 from `problem`'s current values, at most
// settings.max_iterations evaluations; never ends worse than it started.
RunResult epigraph(const ProblemE2& objective, Problem& problem, const OptimizerSettings& settings,
                   EpigraphAlgorithm algorithm);

}  // namespace aapat
