#include "aapat/temporal/model/pan_distribution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "testing/error_message.h"

namespace aapat {
namespace {

// The draws are the seed's, inside the square of max_speed, on the 1/1000
// grid they print on, and spread over it (each quadrant reached).
TEST(PanDistribution, RandomVelocitiesAreTheSeedsWithinTheSpeedOnTheThousandthsGrid) {
  const std::vector<Vec2> v = random_pan_velocities(200, 0.8, 5);
  ASSERT_EQ(v.size(), 200u);
  int quadrants[4] = {0, 0, 0, 0};
  for (const Vec2 p : v) {
    EXPECT_LE(std::abs(p.x), 0.8);
    EXPECT_LE(std::abs(p.y), 0.8);
    EXPECT_EQ(std::round(p.x * 1000) / 1000, p.x);
    EXPECT_EQ(std::round(p.y * 1000) / 1000, p.y);
    ++quadrants[(p.x < 0) + 2 * (p.y < 0)];
  }
  for (const int q : quadrants) EXPECT_GT(q, 30);
  const std::vector<Vec2> again = random_pan_velocities(200, 0.8, 5);
  for (size_t i = 0; i < v.size(); ++i) {
    EXPECT_EQ(again[i].x, v[i].x);
    EXPECT_EQ(again[i].y, v[i].y);
  }
  EXPECT_NE(random_pan_velocities(1, 0.8, 6)[0].x, v[0].x);
  EXPECT_EQ(testing::error_parameter([] { random_pan_velocities(0, 1, 1); }), "random-velocities");
  EXPECT_EQ(testing::error_parameter([] { random_pan_velocities(257, 1, 1); }),
            "random-velocities");
  EXPECT_EQ(testing::error_parameter([] { random_pan_velocities(3, 0, 1); }), "max-speed");
  EXPECT_EQ(testing::error_parameter([] { random_pan_velocities(3, 17, 1); }), "max-speed");
  EXPECT_EQ(testing::error_parameter(
                [] { random_pan_velocities(3, std::numeric_limits<double>::quiet_NaN(), 1); }),
            "max-speed");
}

// Against 0.2, 0.4, 0.5: 0.1 (-50 %), 0.44 (+10 %), 0.5 (0 %): lower at one,
// mean -40/3 %, from -50 % to +10 %.
TEST(PanDistribution, ComparisonCountsAndAveragesTheRelativeChanges) {
  const std::vector<PanReport> theirs{{0.2, 1}, {0.4, 1}, {0.5, 1}};
  const std::vector<PanReport> ours{{0.1, 9}, {0.44, 9}, {0.5, 9}};
  const PanComparison c = compare_pans(ours, theirs);
  EXPECT_EQ(c.lower, 1);
  EXPECT_EQ(c.velocities, 3);
  EXPECT_NEAR(c.mean_change, -0.4 / 3, 1e-15);
  EXPECT_NEAR(c.lowest_change, -0.5, 1e-15);
  EXPECT_NEAR(c.highest_change, 0.1, 1e-15);
  EXPECT_THROW(compare_pans(ours, {{0.2, 1}}), Error);
  EXPECT_THROW(compare_pans({}, {}), Error);
}

}  // namespace
}  // namespace aapat
