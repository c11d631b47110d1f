// The random point processes the optimizer seeds from and the 1D spectra
// sample: jittered, Poisson disk and uniform points, for a tile of pixels
// that repeats (a torus) and on a line. The named 2D generators of `aapat
// generate` (point_generators.h) are the unit-square sets of the literature.
#pragma once

#include <cstdint>
#include <random>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {

enum class SeedKind { kJittered, kPoisson, kUniform };
// "jittered", "poisson" or "uniform"; ParameterError("seeds") otherwise.
SeedKind parse_seed_kind(std::string_view text);

// Positions inside every pixel of a side x side tile, m per pixel, each
// coordinate in [-limit, limit] of its pixel's centre. Jittered and uniform
// treat each pixel alone; Poisson disk throws darts over the whole tile with
// distances measured on the torus (the tile repeats), so samples keep apart
// across pixel borders too.
std::vector<std::vector<Vec2>> tile_points(int side, int m, SeedKind kind, std::mt19937_64& rng,
                                           double limit);

// n points on [0, n) with unit mean spacing (Goss & Wu Fig. 8): "jittered"
// (one per unit interval) or "poisson" (dart throwing, minimum distance 0.6
// on the circle), sorted.
std::vector<double> line_points(std::string_view kind, int n, uint64_t seed);

}  // namespace aapat
