#include "aapat/generate/maximal_poisson.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "aapat/generate/dart_grid.h"
#include "aapat/generate/point_generators.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

double nearest(const std::vector<Vec2>& points, Vec2 c) {
  double best = INFINITY;
  for (const Vec2& p : points) best = std::min(best, torus_distance(p, c));
  return best;
}

// A Poisson-disk set (no two points closer than r) that leaves no spot of
// the torus farther than r from every point, so no further dart could be
// kept: checked by brute force at random spots, for radii from a few
// hundred points down to one (r past 1/sqrt(2) leaves room for one only).
RC_GTEST_PROP(MaximalPoisson, KeepsItsDistanceAndLeavesNoRoom, ()) {
  const double r = *rc::gen::inRange(50, 800) / 1000.0;
  std::mt19937_64 rng(*rc::gen::arbitrary<uint64_t>());
  const std::vector<Vec2> p = maximal_poisson_disk(r, rng);
  RC_ASSERT(!p.empty());
  for (size_t i = 0; i < p.size(); ++i) {
    RC_ASSERT(p[i].x >= 0 && p[i].x < 1 && p[i].y >= 0 && p[i].y < 1);
    for (size_t j = 0; j < i; ++j) RC_ASSERT(torus_distance(p[i], p[j]) >= r);
  }
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < 500; ++k) {
    const Vec2 spot{u(rng), u(rng)};
    RC_ASSERT(nearest(p, spot) < r * (1 + 1e-12));
  }
}

// The same on a dense grid of spots, the old sampler's test, which left
// about 1 spot in 500 free (it stopped after 1000 + 100 n misses in a row).
TEST(MaximalPoisson, NoSpotOfAFineGridIsFree) {
  const double r = 0.1;
  const auto p = generate_points("poisson-maximal:radius=0.1", 1, 5);
  int free_spots = 0;
  for (int i = 0; i < 300; ++i)
    for (int j = 0; j < 300; ++j) free_spots += nearest(p, {(i + 0.5) / 300, (j + 0.5) / 300}) >= r;
  EXPECT_EQ(free_spots, 0);
}

// Darts uniform on the uncovered region until none is left is random
// sequential addition to saturation, whose disks of radius r / 2 cover
// 0.547067 of the plane (Zhang & Torquato 2013); 6 sets of about 14,000
// points average within 0.0015 of it (their spread: about 0.0007 each).
TEST(MaximalPoisson, FillsToTheSaturationCoverageOfRandomSequentialAddition) {
  const double r = 0.007;
  double coverage = 0;
  for (uint64_t seed = 1; seed <= 6; ++seed) {
    std::mt19937_64 rng(seed);
    coverage +=
        static_cast<double>(maximal_poisson_disk(r, rng).size()) * std::numbers::pi * r * r / 4 / 6;
  }
  EXPECT_NEAR(coverage, kRsaSaturationCoverage, 0.0015);
}

TEST(MaximalPoisson, TheSameSeedGivesTheSamePoints) {
  const auto a = generate_points("poisson-maximal", 500, 9),
             b = generate_points("poisson-maximal", 500, 9);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_TRUE(a[i].x == b[i].x && a[i].y == b[i].y);
  EXPECT_NE(generate_points("poisson-maximal", 500, 10)[0].x, a[0].x);
}

// Below the smallest radius a dart grid cell could hold two points: refused
// where the sampler is called, not only where the spec is parsed.
TEST(MaximalPoisson, RefusesARadiusOutOfItsRange) {
  std::mt19937_64 rng(1);
  for (const double r : {1e-5, 0.0, -1.0, 1.5, std::nan("")})
    EXPECT_EQ(testing::error_message([&] { maximal_poisson_disk(r, rng); }),
              fmt::format("poisson-maximal: radius = {} is out of range [0.001, 1] (a maximal set "
                          "of radius r has about 0.7 / r^2 points)",
                          r));
  EXPECT_EQ(testing::error_message([] { generate_points("poisson-maximal", 1000000, 1); }),
            "poisson-maximal: n = 1000000 asks for radius 0.0008059274488676565, below the "
            "smallest, 0.001 (a maximal set of radius r has about 0.7 / r^2 points)");
}

}  // namespace
}  // namespace aapat
