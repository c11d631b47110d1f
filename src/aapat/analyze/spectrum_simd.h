// The exact spectrum's inner loop vectorized with Highway (the best path of
// the processor chosen at run time, as in core/metric_simd.h): lane for lane
// the scalar arithmetic, in the same order, with no fused multiply-add, so
// every path gives the same bits.
#pragma once

#include <cstddef>

namespace aapat {

// The spectrum's sums gain the terms of `points` (at most kPointsAtOnce)
// consecutive points, one after the other: for each point q in order, each
// c < count and v < m,
//   re[c m + v] += ar[q count + c] br[q stride + v] - ai[q count + c] bi[q stride + v],
//   im[c m + v] += ar[q count + c] bi[q stride + v] + ai[q count + c] br[q stride + v],
// where ar + i ai = exp(-2 pi i u x) of column c and br + i bi = exp(-2 pi i v y).
// The sums stay in registers across the points.
inline constexpr size_t kPointsAtOnce = 4;
void add_points_to_columns(size_t points, const double* ar, const double* ai, size_t count,
                           const double* br, const double* bi, size_t stride, size_t m, double* re,
                           double* im);

}  // namespace aapat
