// The star discrepancy of a point set in the unit square: the supremum over
// anchored boxes [0, a) x [0, b) (and their closures) of |fraction of the
// points inside - ab| (docs/analysis.md).
//  - Exact for small sets: every box whose corner coordinates come from the
//    points (or 1), in O(N^2).
//  - Bounds for large ones. Upper: every box lies between two boxes of a
//    grid x grid lattice, and its deviation is at most the worse mixed
//    comparison of the two (O(grid^2 + N) time, O(grid + N) memory; the
//    bound cannot go below about 2 / grid). Lower: the exact deviation of
//    real boxes, found by starting from the lattice's worst boxes and
//    moving one corner coordinate at a time to its exact best position
//    among the points' coordinates (each move an O(N) sweep), until no move
//    improves. Thiemard's bracketing bounds the same supremum; at 16k and
//    65k Halton points this gives tighter bounds on both sides
//    (docs/benchmarks.md).
#pragma once

#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

struct StarDiscrepancy {
  double lower = 0, upper = 0;  // equal when exact
  bool exact = false;
};
StarDiscrepancy star_discrepancy(const std::vector<Vec2>& points, size_t exact_limit = 4096,
                                 int grid = 8192);

}  // namespace aapat
