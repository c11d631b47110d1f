#include "aapat/generate/dart_grid.h"

#include <gtest/gtest.h>

namespace aapat {
namespace {

// At r = 1e-5 the grid stops at 2048 cells a side (each 4.9e-4 wide), so
// two points of a Poisson-disk set can share a cell: each must still answer
// for the spots near it.
TEST(DartGrid, AClampedGridKeepsEveryPointOfACell) {
  const double r = 1e-5;
  DartGrid grid(r);
  ASSERT_EQ(grid.side(), DartGrid::kMaxSide);
  const Vec2 first{0.50001, 0.5}, second{0.50005, 0.5};  // one cell, 4e-5 apart
  ASSERT_EQ(grid.cell(first.x), grid.cell(second.x));
  grid.add(first);
  grid.add(second);
  EXPECT_TRUE(grid.any_within({0.500005, 0.5}, r));  // 5e-6 from the first only
  EXPECT_TRUE(grid.any_within({0.500055, 0.5}, r));  // 5e-6 from the second only
  EXPECT_FALSE(grid.any_within({0.50003, 0.5}, r));  // 2e-5 from both
}

// Across the torus' seam: a point near x = 1 is near a spot near x = 0.
TEST(DartGrid, DistancesWrapAroundTheTorus) {
  DartGrid grid(0.05);
  grid.add({0.99, 0.5});
  EXPECT_TRUE(grid.any_within({0.02, 0.5}, 0.05));
  EXPECT_FALSE(grid.any_within({0.05, 0.5}, 0.05));
  EXPECT_NEAR(torus_distance({0.99, 0.01}, {0.01, 0.99}), std::hypot(0.02, 0.02), 1e-15);
}

}  // namespace
}  // namespace aapat
