// Maximal Poisson-disk sampling on the unit torus: random sequential addition
// (uniform darts, each kept unless it falls within r of a kept one) run until
// no spot of the torus is farther than r from every point, so that no other
// dart could be kept: the `poisson-maximal` generator.
#pragma once

#include <random>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/work/work_items.h"

namespace aapat {

// Darts fall uniformly in the "active" cells, squares of one size that may
// still hold an uncovered spot; after each round every active cell is split
// in four and the children that one point's disk covers whole are dropped
// (Ebeida et al. 2011, "Efficient maximal Poisson-disk sampling"). The active
// cells always hold every uncovered spot, so a kept dart is uniform on the
// uncovered region, as in plain dart throwing; the sampling stops when no
// active cell is left (or, in floating point, none wider than 1e-12 r).
// r in [kMinMaximalPoissonRadius, 1], else an Error (the dart grid holds one
// point per cell down to that radius, about 700,000 points); `progress`
// hears of the points kept against the set's expected size.
inline constexpr double kMinMaximalPoissonRadius = 1e-3;
std::vector<Vec2> maximal_poisson_disk(double r, std::mt19937_64& rng,
                                       const ItemsProgress& progress = {});

// The saturation coverage of random sequential addition of disks in the
// plane: a maximal set of minimum distance r has about this fraction of the
// torus under its disks of radius r / 2, i.e. about 0.6966 / r^2 points
// (Zhang & Torquato 2013, Phys. Rev. E 88, 053312: 0.547067).
inline constexpr double kRsaSaturationCoverage = 0.547067;

}  // namespace aapat
