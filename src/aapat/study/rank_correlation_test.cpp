#include "aapat/study/rank_correlation.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

namespace aapat {
namespace {

TEST(RankCorrelation, MeanRanksOfTies) {
  EXPECT_EQ(mean_ranks(std::vector<double>{10, 30, 20, 30}), (std::vector<double>{1, 3.5, 2, 3.5}));
}

// Monotone in either direction: +1 and -1; any strictly increasing
// transformation of one side changes neither.
TEST(RankCorrelation, MonotoneIsOne) {
  const std::vector<double> a{1, 2, 3, 4, 5, 6}, b{2, 4, 8, 16, 32, 64}, c{6, 5, 4, 3, 2, 1};
  EXPECT_DOUBLE_EQ(spearman(a, b), 1);
  EXPECT_DOUBLE_EQ(kendall_tau_b(a, b), 1);
  EXPECT_DOUBLE_EQ(spearman(a, c), -1);
  EXPECT_DOUBLE_EQ(kendall_tau_b(a, c), -1);
  EXPECT_TRUE(std::isnan(spearman(a, std::vector<double>(6, 1.0))));
}

// Hand-computed values. Kendall: pairs of (1,2,3,4,5) and (3,1,2,5,4): 10
// pairs, 7 concordant, 3 discordant, tau = 0.4; Spearman: sum d^2 = 8,
// rho = 1 - 6 * 8 / (5 * 24) = 0.6. With ties, tau-b: x = (1,2,2,3),
// y = (1,3,2,4): of 6 pairs 5 concordant, none discordant, one tied in x,
// so tau-b = 5 / sqrt((5 + 0 + 0)(5 + 0 + 1)).
TEST(RankCorrelation, HandComputedValues) {
  const std::vector<double> a{1, 2, 3, 4, 5}, b{3, 1, 2, 5, 4};
  EXPECT_NEAR(kendall_tau_b(a, b), 0.4, 1e-15);
  EXPECT_NEAR(spearman(a, b), 0.6, 1e-15);
  const std::vector<double> x{1, 2, 2, 3}, y{1, 3, 2, 4};
  EXPECT_NEAR(kendall_tau_b(x, y), 5.0 / std::sqrt(30.0), 1e-15);
}

// The bootstrap interval holds the statistic's value for data with a clear
// trend, narrows as the sample grows, and is the same for the same seed.
TEST(RankCorrelation, BootstrapIntervals) {
  std::vector<double> x, y;
  for (int i = 0; i < 60; ++i) {
    x.push_back(i);
    y.push_back(i + 25 * std::sin(i * 1.7));  // a trend with noise
  }
  const RankCorrelation r = rank_correlation(x, y, 2000, 0.95, 7);
  EXPECT_LE(r.spearman.low, r.spearman.value);
  EXPECT_GE(r.spearman.high, r.spearman.value);
  EXPECT_LE(r.kendall.low, r.kendall.value);
  EXPECT_GE(r.kendall.high, r.kendall.value);
  EXPECT_GT(r.spearman.low, 0.5);
  const RankCorrelation again = rank_correlation(x, y, 2000, 0.95, 7);
  EXPECT_EQ(again.spearman.low, r.spearman.low);
  EXPECT_EQ(again.kendall.high, r.kendall.high);
  const std::vector<double> few_x(x.begin(), x.begin() + 15), few_y(y.begin(), y.begin() + 15);
  const RankCorrelation few = rank_correlation(few_x, few_y, 2000, 0.95, 7);
  EXPECT_GT(few.spearman.high - few.spearman.low, r.spearman.high - r.spearman.low);
}

// Both statistics lie in [-1, 1] and are symmetric in their arguments.
RC_GTEST_PROP(RankCorrelation, BoundedAndSymmetric, ()) {
  const auto a = *rc::gen::container<std::vector<int>>(12, rc::gen::inRange(0, 6));
  const auto b = *rc::gen::container<std::vector<int>>(12, rc::gen::inRange(0, 6));
  const std::vector<double> x(a.begin(), a.end()), y(b.begin(), b.end());
  for (const double v : {spearman(x, y), kendall_tau_b(x, y)})
    if (!std::isnan(v)) RC_ASSERT(v >= -1 - 1e-12 && v <= 1 + 1e-12);
  const double s1 = spearman(x, y), s2 = spearman(y, x);
  RC_ASSERT((std::isnan(s1) && std::isnan(s2)) || std::abs(s1 - s2) <= 1e-12);
  const double k1 = kendall_tau_b(x, y), k2 = kendall_tau_b(y, x);
  RC_ASSERT((std::isnan(k1) && std::isnan(k2)) || std::abs(k1 - k2) <= 1e-12);
}

}  // namespace
}  // namespace aapat
