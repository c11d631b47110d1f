// Uniform random points in the unit square for the point-set tests: the same
// n points for the same seed.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat::testing {

inline std::vector<Vec2> random_points(uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec2> p(static_cast<size_t>(n));
  for (auto& v : p) v = {u(rng), u(rng)};
  return p;
}

}  // namespace aapat::testing
