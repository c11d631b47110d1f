// Sorting doubles by their bits: six passes of 11-bit counting sort over a
// key that orders like the numbers (the sign bit flipped, and every bit for
// negatives). O(N) where std::sort is O(N log N): the edge discrepancy sorts
// 65,536 projections for each of 720 directions. Small inputs go to
// std::sort. Finite values only; -0.0 sorts just before +0.0.
#pragma once

#include <cstdint>
#include <vector>

namespace aapat {

// Sorts `values` ascending; `scratch` is reused between calls (no allocation
// once it has grown).
void radix_sort(std::vector<double>& values, std::vector<uint64_t>& scratch);

}  // namespace aapat
