// E2 of many one-pixel patterns at once (P(1,1,n): n samples and weights
// each), as `aapat.eval` evaluates an (m, n, 2) numpy array: one kernel per
// pattern straight from the arrays, in parallel over patterns (oneTBB; each
// result depends on its pattern alone, so any thread count gives the same).
#pragma once

#include <cstddef>
#include <span>

#include "aapat/core/metric.h"

namespace aapat {

// xy: m * n * 2 coordinates (pattern-major, then sample, then x, y), pixels
// from the pixel centre; weights: m * n, or empty for equal weights (each
// pattern's weights are normalized by their sum). Writes m values to e2.
// Error for a size that does not match, a coordinate or weight that is not
// finite, or weights that sum to zero.
void batch_e2(const Metric& metric, std::span<const double> xy, std::span<const double> weights,
              size_t patterns, size_t samples, std::span<double> e2);

// The same patterns' per-angle profiles W(theta) E1(theta): patterns *
// angle_count() values, pattern-major, into `profile` (E2 is each row's
// combination over angles).
void batch_profile(const Metric& metric, std::span<const double> xy,
                   std::span<const double> weights, size_t patterns, size_t samples,
                   std::span<double> profile);

}  // namespace aapat
