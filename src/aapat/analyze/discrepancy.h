// Discrepancy of a point set in the unit square (docs/analysis.md):
//  - L2-star: the L2 norm over anchored boxes [0,a) x [0,b) of
//    (fraction of points inside - area), by Warnock's closed form, summed
//    in O(N log N); the other L2 kinds in l2_discrepancy.h;
//  - star: the supremum of the same (star_discrepancy.h);
//  - edge: the supremum over half-planes H of |area(H cut with the square) -
//    fraction of points in H|, in the spirit of Dobkin & Mitchell: exact for
//    each direction, over `directions` directions of the edge normal.
#pragma once

#include <functional>
#include <vector>

#include "aapat/analyze/star_discrepancy.h"
#include "aapat/core/geometry.h"
#include "aapat/core/half_plane_area.h"

namespace aapat {

// The star discrepancy is exact in O(N^2 log N) up to its exact limit and the
// edge discrepancy O(directions N log N): larger sets are refused
// (docs/limits.md) rather than run for hours. The L2-star discrepancy is
// O(N log N) and takes far more.
inline constexpr size_t kMaxDiscrepancyPoints = 65536;
inline constexpr size_t kMaxL2StarPoints = 10'000'000;
// Throw Error naming the count and the limit.
void check_discrepancy_size(size_t points);
void check_l2_star_size(size_t points);

// Warnock's closed form in O(N log N) with double-double sums: correct to
// about 1e-12 relative at any size up to kMaxL2StarPoints.
double l2_star_discrepancy(const std::vector<Vec2>& points);

struct EdgeDiscrepancy {
  double value = 0;
  double normal_deg = 0;  // direction of the worst half-plane's normal
};
// `progress(done, total)` hears each direction finish.
EdgeDiscrepancy edge_discrepancy(const std::vector<Vec2>& points, int directions = 720,
                                 const std::function<void(int, int)>& progress = {});

}  // namespace aapat
