// What the optimizer varies: a pattern seen as a few free parameters.
//
// A *generator* is one sample position the optimizer moves, with its freedom:
// free inside its pixel, sliding along the border it lies on, or fixed (a
// corner, or a sample the user locked). Every sample of every set and every
// sample a kernel reads is a generator mapped by a mirror (sx, sy) and a
// translation, so shared border samples, mirrored P(4,1+,n) tiles and
// repeated sets (P(1,4,n)) keep one position for all who read them. Each
// kernel keeps its own weights (weight variables in groups that sum to 1;
// the kernels of a mirrored tile share one group).
#pragma once

#include <random>
#include <string>
#include <vector>

#include "aapat/core/pattern.h"

namespace aapat {

enum class Freedom { kFree, kSlideX, kSlideY, kFixed };

struct Generator {
  Vec2 pos;  // in its own pixel's frame
  Freedom freedom = Freedom::kFree;
  double limit = 0.5;  // |x|, |y| <= limit along the free directions
};

// A use of a generator: position = (sx * g.x + offset.x, sy * g.y + offset.y).
struct Placement {
  int generator = 0;
  double sx = 1, sy = 1;
  Vec2 offset;
  Vec2 at(const std::vector<Generator>& g) const {
    return {sx * g[generator].pos.x + offset.x, sy * g[generator].pos.y + offset.y};
  }
};

struct KernelRead {
  Placement place;  // relative to the kernel's output point
  int weight = 0;   // index into Problem::weights
};

struct Problem {
  Pattern layout;  // names, tile, footprint and provenance of the result
  std::vector<Generator> generators;
  std::vector<double> weights;
  std::vector<std::vector<int>> weight_groups;      // each group sums to 1
  std::vector<std::vector<Placement>> set_samples;  // per set, per sample
  std::vector<std::vector<KernelRead>> kernels;     // per kernel, in kernel_samples order
};

// Every physical sample of the pattern becomes a generator; a mirrored 2x2
// tile (Hasselgren's P(4,1+,n)) is recognized and keeps its symmetry.
Problem problem_from_pattern(const Pattern& p);
// The mirrored P(4,1+,n) tile from a base set, its symmetry built in.
Problem mirrored_problem(const Pattern& mirrored_tile);
// The pattern the problem's current values describe.
Pattern pattern_of(const Problem& problem);
// Whether a 2x2 1+ tile is the mirror construction of its first set.
bool is_mirrored_tile(const Pattern& p);

// Fixes the generators of the given samples of set 0 (the base pixel), so the
// optimizer leaves them where they are; throws Error for an index out of range.
void lock_samples(Problem& problem, const std::vector<int>& set0_samples);

// A nearby start: every free coordinate moved uniformly by up to +-amount
// pixels, then put back on the constraints.
Problem perturbed(const Problem& problem, double amount, std::mt19937_64& rng);

// How far inside its pixel a sample of a family without shared borders is
// kept by keep_strictly_inside: a sample on the border would read as one its
// neighbour shares (a P(1,1,12) search that put samples on both sides of the
// pixel became P(1,1,9)); 1/64 pixel is a quarter of the API lattice's step.
inline constexpr double kInsideMargin = 1.0 / 64;

// Keeps the free samples of a family without shared borders at least
// `margin` inside the pixel (their limit, then projected): the catalog's
// aapat-N hold N samples strictly inside, as plain MSAA needs. Sharing
// footprints already keep their inside samples off the border.
void keep_strictly_inside(Problem& problem, double margin = kInsideMargin);

// Keeps every generator inside its freedom and limits, and (optionally
// non-negative) weights summing to 1 in each group.
void project_to_constraints(Problem& problem, bool nonnegative_weights);

}  // namespace aapat
