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

// The same walk from the vectors themselves, for vectors shorter than they
// are many: q = A^T x with x = sum lambda_i g_i kept as the walk moves costs
// m dim per step instead of m^2 (a weights-only direction: 80 terms in 6
// weights). The same steps up to rounding, so not the same bits as the Gram
// form. columns: dim x m, column c holding every vector's coordinate c.
std::vector<double> min_norm_combination_of_vectors(std::span<const double> columns, size_t m,
                                                    size_t dim, int iterations = 200);

}  // namespace aapat
