// Jitters judged over a distribution of pans rather than at a few chosen
// velocities: under a sharp history (FSR 2's Lanczos-2) which jitter wins at
// one velocity swings by tens of percent with the velocity, so a comparison
// means something only over many (docs/temporal.md, "Under motion").
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "aapat/core/geometry.h"
#include "aapat/temporal/model/pan_model.h"

namespace aapat {

inline constexpr int kMaxRandomPanVelocities = 256;
inline constexpr double kDefaultRandomPanSpeed = 1.5;

// `count` velocities, each component uniform in [-max_speed, max_speed]
// display pixels per frame from the seed (std::mt19937_64, x before y),
// rounded to 1/1000 so that they print as they are used. Throws
// ParameterError naming "random-velocities" or "max-speed".
std::vector<Vec2> random_pan_velocities(int count, double max_speed, uint64_t seed);

// The velocities at which the common jitters collapse (docs/temporal.md,
// "What a jitter can deliver"), in render pixels per frame: every pair of
// components from {0, 1/4, -1/4, 1/3, -1/3, 1/2} (Halton's base 2 pairs its
// samples at 1/2, base 3 groups them in threes at 1/3, base-2 nets such as
// Sobol's partly at 1/4; both signs, since which one lines the samples up
// depends on the jitter's sign and the pan's direction), x before y, then
// R2's own step (1/g, 1/g^2) and its negative. 38 velocities.
std::vector<Vec2> resonant_velocities();

// What `sequence pan` and Python's sequence_pan evaluate: the velocities
// given (none given: default_pan_velocities(), unless random ones are
// asked for), then `random_count` random ones (0: none).
std::vector<Vec2> pan_velocities(const std::optional<std::vector<Vec2>>& given, int random_count,
                                 double max_speed, uint64_t seed);

// One sequence's steady mean E2 against another's (the first of a
// comparison) at the same velocities: at how many it is lower, and the
// relative change (E2 / theirs - 1) on average, at its lowest and highest.
struct PanComparison {
  int lower = 0, velocities = 0;
  double mean_change = 0, lowest_change = 0, highest_change = 0;
};
PanComparison compare_pans(const std::vector<PanReport>& ours,
                           const std::vector<PanReport>& theirs);

}  // namespace aapat
