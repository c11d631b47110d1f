#include "aapat/optimize/compass_search.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

// On a separable quadratic whose minimum lies on the step's lattice the
// search lands on it exactly, and every try it counts is one evaluation.
TEST(CompassSearch, LandsOnAQuadraticsMinimumOnItsLattice) {
  int evaluations = 0;
  FunctionObjective f(
      [&](std::span<const double> x) {
        ++evaluations;
        return (x[0] - 0.25) * (x[0] - 0.25) + 2 * (x[1] + 0.125) * (x[1] + 0.125) +
               (x[2] - 0.375) * (x[2] - 0.375) + 1;
      },
      1);
  CompassSettings s;
  s.block_size = 1;
  s.step = 1.0 / 8;
  s.min_step = 1.0 / 64;
  const CompassResult r = compass_search(f, {0, 0, 0}, s);
  EXPECT_DOUBLE_EQ(r.x[0], 0.25);
  EXPECT_DOUBLE_EQ(r.x[1], -0.125);
  EXPECT_DOUBLE_EQ(r.x[2], 0.375);
  EXPECT_DOUBLE_EQ(r.value, 1);
  EXPECT_DOUBLE_EQ(r.start_value, 1 + 0.0625 + 2 * 0.015625 + 0.140625);
  EXPECT_GT(r.kept, 0);
  // One set to start and one per sweep, besides the tries.
  EXPECT_GT(evaluations, r.tries);
}

// Over random smooth objectives and starts: never above the start, inside
// the bounds, and the same result run twice; max_tries bounds the work.
RC_GTEST_PROP(CompassSearch, NeverEndsAboveItsStartNorLeavesTheBounds, ()) {
  const int n = *rc::gen::inRange(1, 4) * 2;
  std::vector<double> centre, start;
  for (int i = 0; i < n; ++i) {
    centre.push_back(*rc::gen::inRange(-100, 100) / 100.0);
    start.push_back(*rc::gen::inRange(-40, 40) / 100.0);
  }
  const auto value = [&](std::span<const double> x) {
    double v = 0;
    for (size_t i = 0; i < x.size(); ++i)
      v += std::cos(3 * x[i]) + (x[i] - centre[i]) * (x[i] - centre[i]);
    return v + 10;
  };
  CompassSettings s;
  s.lo = -0.4;
  s.hi = 0.4;
  s.max_tries = *rc::gen::inRange(0, 50);
  FunctionObjective f(value, s.block_size), g(value, s.block_size);
  const CompassResult a = compass_search(f, start, s), b = compass_search(g, start, s);
  RC_ASSERT(a.value <= a.start_value);
  RC_ASSERT(a.x == b.x);
  if (s.max_tries > 0) RC_ASSERT(a.tries <= s.max_tries);
  for (const double v : a.x) RC_ASSERT(v >= s.lo && v <= s.hi);
  RC_ASSERT(std::abs(value(a.x) - a.value) <= 1e-12 * a.value);
}

TEST(CompassSearch, RefusesSettingsByName) {
  FunctionObjective f([](std::span<const double>) { return 1.0; }, 2);
  CompassSettings s;
  s.step = 0;
  EXPECT_THROW(compass_search(f, {0, 0}, s), ParameterError);
  s = {};
  s.min_step = 1;
  EXPECT_THROW(compass_search(f, {0, 0}, s), ParameterError);
  s = {};
  EXPECT_THROW(compass_search(f, {0, 0, 0}, s), Error);  // not whole blocks
  EXPECT_THROW(compass_search(f, {0.7, 0}, s), Error);   // outside the bounds
}

}  // namespace
}  // namespace aapat
