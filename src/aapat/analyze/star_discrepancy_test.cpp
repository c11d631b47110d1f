#include "aapat/analyze/star_discrepancy.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "testing/random_points.h"

#include "aapat/generate/point_generators.h"

namespace aapat {
namespace {

using testing::random_points;

// One point at (a, b): the empty boxes reach area max(a, b), the boxes
// holding it fall short by 1 - ab at worst.
TEST(StarDiscrepancy, SinglePointClosedForm) {
  for (const Vec2 p : {Vec2{0.5, 0.5}, Vec2{0.2, 0.9}, Vec2{0.7, 0.1}}) {
    const auto d = star_discrepancy({p});
    EXPECT_TRUE(d.exact);
    EXPECT_NEAR(d.upper, std::max({p.x, p.y, 1 - p.x * p.y}), 1e-15);
  }
}

// The centres of a k x k grid: D* = 1 - (1 - 1/(2k))^2.
TEST(StarDiscrepancy, RegularGridClosedForm) {
  for (int k : {2, 4, 7}) {
    std::vector<Vec2> p;
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) p.push_back({(i + 0.5) / k, (j + 0.5) / k});
    EXPECT_NEAR(star_discrepancy(p).upper, 1 - std::pow(1 - 0.5 / k, 2), 1e-12) << k;
  }
}

// Against brute force: every box corner on a fine grid (a lower bound that
// reaches the exact value at the points' own coordinates) and the grid bounds.
RC_GTEST_PROP(StarDiscrepancy, ExactAgreesWithBruteForceAndBounds, ()) {
  const auto p = random_points(*rc::gen::arbitrary<uint64_t>(), *rc::gen::inRange(1, 40));
  const double exact = star_discrepancy(p).upper;
  double brute = 0;
  std::vector<double> xs{1}, ys{1};
  for (const Vec2& v : p) xs.push_back(v.x), ys.push_back(v.y);
  for (double a : xs)
    for (double b : ys) {
      int open = 0, closed = 0;
      for (const Vec2& v : p) {
        open += v.x < a && v.y < b;
        closed += v.x <= a && v.y <= b;
      }
      brute = std::max({brute, a * b - double(open) / p.size(), double(closed) / p.size() - a * b});
    }
  RC_ASSERT(std::abs(exact - brute) <= 1e-15);
  const auto bounds = star_discrepancy(p, 0, 256);
  RC_ASSERT(!bounds.exact);
  RC_ASSERT(bounds.lower <= exact + 1e-12);
  RC_ASSERT(exact <= bounds.upper + 1e-12);
}

// The bounds' lower end is the deviation of real boxes found by climbing from
// the lattice's worst: on these sets it reaches the exact value, where the
// lattice boxes alone stay below it.
TEST(StarDiscrepancy, TheClimbReachesTheExactValueOnTheseSets) {
  for (const char* generator : {"halton", "jittered", "random", "poisson", "hammersley"}) {
    const auto p = generate_points(generator, 2025, 3);
    const StarDiscrepancy exact = star_discrepancy(p), bounds = star_discrepancy(p, 0, 4096);
    ASSERT_TRUE(exact.exact);
    EXPECT_FALSE(bounds.exact);
    EXPECT_DOUBLE_EQ(bounds.lower, exact.upper) << generator;
    EXPECT_LE(exact.upper, bounds.upper) << generator;
    EXPECT_LT(bounds.upper - bounds.lower, 2.0 / 4096 + 1e-12) << generator;
  }
}

// The lattice runs in parallel chunks of columns: the same bounds on one thread.
TEST(StarDiscrepancy, TheSameBoundsOnAnyNumberOfThreads) {
  const auto p = generate_points("halton", 20000, 1);
  StarDiscrepancy one;
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    one = star_discrepancy(p, 0, 2048);
  }
  const StarDiscrepancy all = star_discrepancy(p, 0, 2048);
  EXPECT_EQ(one.lower, all.lower);
  EXPECT_EQ(one.upper, all.upper);
}

// Any set: the bounds bracket the exact value.
RC_GTEST_PROP(StarDiscrepancy, TheBoundsBracketTheExactValue, ()) {
  const auto p = random_points(*rc::gen::arbitrary<uint64_t>(), *rc::gen::inRange(1, 400));
  const double exact = star_discrepancy(p).upper;
  const auto bounds = star_discrepancy(p, 0, *rc::gen::element(16, 64, 1024));
  RC_ASSERT(bounds.lower <= exact + 1e-15);
  RC_ASSERT(exact <= bounds.upper + 1e-12);
}

}  // namespace
}  // namespace aapat
