// Sums over all ordered pairs (i, j) of a point set, in O(N log N) instead of
// O(N^2), in double-double (the L2 discrepancies are tiny differences of such
// sums). Every L2 discrepancy's pair kernel is, per coordinate, a polynomial
// of degree at most 2 in each of u and v plus a multiple of min(u, v)
// (|u - v| = u + v - 2 min(u, v)), so these three sums are all it needs:
//  - moments sum_i a_i^p b_i^q,
//  - sum_ij Q(a_i, a_j) min(b_i, b_j), Q a polynomial of degree 2 in each
//    variable: one sort of b and prefix sums,
//  - sum_ij min(a_i, a_j) min(b_i, b_j): a sweep in a with a Fenwick tree over
//    the ranks of b (the structure of Heinrich's algorithm for Warnock's sum).
#pragma once

#include <span>
#include <vector>

#include "aapat/analyze/double_double.h"

namespace aapat {

// Strict order of double-doubles in normal form (hi = hi + lo rounded).
inline bool operator<(DoubleDouble a, DoubleDouble b) {
  return a.hi < b.hi || (a.hi == b.hi && a.lo < b.lo);
}

// The indices 0 .. n-1 sorted by v ascending (ties by index: deterministic).
std::vector<size_t> ascending_order(std::span<const DoubleDouble> v);

// sum_i a_i^p b_i^q for p, q in 0..2: moment[p][q].
using Moments = DoubleDouble[3][3];
void moments(std::span<const DoubleDouble> a, std::span<const DoubleDouble> b, Moments& out);

// sum over all ordered pairs, i = j included, of
//   sum_pq q[p][r] a_i^p a_j^r min(b_i, b_j).
using PairPolynomial = double[3][3];
// `b_order` is ascending_order(b).
DoubleDouble polynomial_min_sum(const PairPolynomial& q, std::span<const DoubleDouble> a,
                                std::span<const DoubleDouble> b, std::span<const size_t> b_order);

// sum over all ordered pairs of min(a_i, a_j) min(b_i, b_j), i = j included,
// with the ascending orders of a and b.
DoubleDouble min_min_sum(std::span<const DoubleDouble> a, std::span<const DoubleDouble> b,
                         std::span<const size_t> a_order, std::span<const size_t> b_order);

}  // namespace aapat
