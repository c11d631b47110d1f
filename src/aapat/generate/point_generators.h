// Point-set generators in the unit square [0,1)^2 (Pelikan's slides; Goss &
// Wu Sec. 3.2): regular, random, jittered, semi-jittered, N-rooks, N-queens,
// Poisson disk (and its maximal variant), Mitchell's best candidate,
// Hammersley, Halton and Larcher-Pillichshammer. Each takes a seed (the
// deterministic ones ignore it); specs read like `halton:b1=2,b2=3`.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/core/pattern.h"
#include "aapat/core/spec.h"
#include "aapat/work/work_items.h"

namespace aapat {

// Mitchell's best candidate costs q n^2 / 2 nearest-point queries; past this
// many it is refused (docs/limits.md).
// Points one generator makes, and the largest N of the N-queens search (the
// lexicographic search takes 40 s at N = 32).
inline constexpr int kMaxGeneratedPoints = 1'000'000;
// Realizations at once, and their points in all (16 bytes each: 800 MB).
inline constexpr int kMaxPointSets = 100'000;
inline constexpr int64_t kMaxGeneratedPointsInAll = 50'000'000;
inline constexpr int kMaxNQueens = 20;
inline constexpr double kMaxBestCandidateQueries = 5e7;  // about 7 s on one core

// Dart throwing (poisson) past this many points is refused; poisson-maximal
// is bounded by its radius (r >= 0.001: about 700,000 points).
inline constexpr int kMaxPoissonPoints = 200'000;  // about 8 s on one core

// The point generator `spec` with its parameters parsed once, for drawing many
// point sets (the renderer draws one per pixel).
// The slow ones (dart throwing, best candidate, the N-queens search) tell
// `progress` how far they are (Hundredths), the others nothing.
using PointGenerator =
    std::function<std::vector<Vec2>(int n, uint64_t seed, const ItemsProgress& progress)>;
// Every generator with its parameters (core/spec.h).
using GeneratorRegistry = Registry<PointGenerator>;
const GeneratorRegistry& generator_registry();

// n points in [0,1)^2 by the generator `spec`; throws Error naming the
// generator, parameter or n that does not fit.
std::vector<Vec2> generate_points(std::string_view spec, int n, uint64_t seed,
                                  const ItemsProgress& progress = {});
// `sets` realizations, with seeds seed, seed + 1, ... (as `aapat generate
// --sets`), at most kMaxPointSets of them and kMaxGeneratedPointsInAll points
// in all; each set is a work item (work/work_items.h), so they run on every
// core with the same result, and `progress` hears of each (of one set: its
// generator's hundredths).
std::vector<std::vector<Vec2>> generate_point_sets(std::string_view spec, int n, uint64_t seed,
                                                   int sets, const ItemsProgress& progress = {});

PointGenerator make_point_generator(std::string_view spec);

// The radical inverse g_b(i) of Pelikan's slides: the base-b digits of i
// mirrored about the radix point.
double radical_inverse(uint64_t i, int base);
// Larcher-Pillichshammer's inverse: i's bits through the all-ones upper
// triangular matrix (XOR instead of the sum), a (0, m, 2)-net with i / 2^m.
double larcher_pillichshammer(uint32_t i);

// Every N-queens placement on an N x N grid (row r holds column q[r]),
// in lexicographic order, at most `limit` of them.
std::vector<std::vector<int>> n_queens_solutions(int n, size_t limit);

// One pixel's pattern (P(1,1,n), equal weights) from points in [0,1)^2.
Pattern points_to_pattern(const std::vector<Vec2>& unit_points, std::string name);

// A k x k tile of independently generated pixel sets: P(k^2, 1, n), equal
// weights; pixel (x, y) draws from seed_for_pixel(seed, x, y).
Pattern tile_pattern(std::string_view spec, int n, uint64_t seed, int k);

// The pattern of any pixel of an image, in its local frame [-0.5, 0.5)^2,
// for per-pixel jittered (or any generator's) sampling: the same seed and
// pixel give the same points, in any order of pixels or threads.
std::vector<Vec2> pixel_points(std::string_view spec, int n, uint64_t seed, int x, int y);
std::vector<Vec2> pixel_points(const PointGenerator& generator, int n, uint64_t seed, int x, int y);
uint64_t seed_for_pixel(uint64_t seed, int x, int y);

}  // namespace aapat
