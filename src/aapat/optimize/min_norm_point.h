// The point of smallest norm in the convex hull of m vectors, given their
// Gram matrix: Frank-Wolfe with an exact line search (the minimax descent's
// direction, Demyanov's eps-steepest descent; problem_e2.h).
#pragma once

#include <span>
#include <vector>

namespace aapat {

// The weights lambda (>= 0, summing to 1) of the convex combination, after
// at most `iterations` Frank-Wolfe steps from the centroid. gram: m x m,
// symmetric, row-major. G lambda runs with the lanes over rows (Highway,
// chosen at run time), each entry summed over columns in order: the same bits
// on every path.
std::vector<double> min_norm_combination(std::span<const double> gram, size_t m,
                                         int iterations = 200);

}  // namespace aapat
