// Simulated annealing over the same parameters, the standard alternative that
// Laine & Aila (Sec. 5) report stalls once several terms sit near the maximum.
// Kept selectable (`--method anneal`) so the two can be compared on the same starts.
#pragma once

#include <random>

#include "aapat/optimize/problem_e2.h"
#include "aapat/optimize/settings.h"

namespace aapat {

RunResult anneal(const ProblemE2& objective, Problem& problem, const OptimizerSettings& settings,
                 std::mt19937_64& rng);

}  // namespace aapat
