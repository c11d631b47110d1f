// The L2 discrepancies of a point set in the unit square (docs/analysis.md):
// the L2 norm of the local discrepancy (fraction of points in a box - its
// area) over a family of boxes. Each has Hickernell's closed form
//   D^2 = prod_k (a + K) - (2/N) sum_i prod_k (a + C(x_ik))
//         + (1/N^2) sum_ij prod_k (a + A(x_ik, x_jk)),
// with per-coordinate terms A, C, K of the 1D box family and a = 1 where the
// norm also covers the boxes of every projection (Hickernell 1998), a = 0
// where it covers the full-dimensional boxes only:
//  - star (Warnock): boxes [0, t), a = 0;
//  - generalized (Hickernell's): the star boxes and their projections, a = 1;
//  - centred: the box between t and its nearest corner, with projections;
//  - wrap-around: every box on the torus, with projections;
//  - unanchored: every box [s, t) with s < t, a = 0;
//  - symmetric: Hickernell's reflection-invariant kernel, with projections;
//  - mixture: Zhou, Fang & Ning's mixture discrepancy (MD, 2013), whose
//    pair term mixes the centred (|u - 1/2|) and wrap-around (|u - v|) ones:
//      A = 15/8 - |s - 1/2|/4 - |t - 1/2|/4 - 3|s - t|/4 + |s - t|^2/2,
//      C = 5/3 - |s - 1/2|/4 - |s - 1/2|^2/4,  K = 19/12.
// Every value returned is the discrepancy D itself, not D^2 (scipy.stats.qmc
// returns the centred, wrap-around and mixture ones squared, L2-star not).
// All are summed in O(N log N) in double-double (analyze/pair_sums.h):
// correct to about 1e-12 relative at any size up to kMaxL2StarPoints.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

enum class L2Kind { star, generalized, centred, wrap_around, unanchored, symmetric, mixture };

struct L2KindInfo {
  L2Kind kind;
  std::string_view name;   // "l2-star", as --measure takes it
  std::string_view key;    // "l2_star", the JSON and Python key
  std::string_view label;  // "L2-star", for text reports
  std::string_view boxes;  // what it measures, one line
};
// Every kind, in the order above.
std::span<const L2KindInfo> l2_kinds();
const L2KindInfo& l2_kind_info(L2Kind kind);

// The L2 discrepancy of `kind`; an empty set gives the norm of the boxes'
// areas alone. Throws Error past kMaxL2StarPoints.
double l2_discrepancy(const std::vector<Vec2>& points, L2Kind kind);

}  // namespace aapat
