#include "aapat/analyze/paired_comparison.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <vector>

#include "aapat/core/geometry.h"

namespace aapat {
namespace {

// n of n lower: P = 2 / 2^n; an even split: P = 1; the binomial sum itself.
TEST(SignTest, IsTheExactBinomialTail) {
  EXPECT_DOUBLE_EQ(sign_test_p(10, 0), 2.0 / 1024);
  EXPECT_DOUBLE_EQ(sign_test_p(0, 10), 2.0 / 1024);
  EXPECT_DOUBLE_EQ(sign_test_p(5, 5), 1.0);
  // 8 of 10: 2 (1 + 10 + 45) / 1024.
  EXPECT_NEAR(sign_test_p(8, 2), 2.0 * 56 / 1024, 1e-15);
  EXPECT_DOUBLE_EQ(sign_test_p(0, 0), 1.0);
  EXPECT_GT(sign_test_p(2000, 0), 0.0 - 1e-300);  // no overflow or NaN past 2^-1074
  EXPECT_FALSE(std::isnan(sign_test_p(1500, 1400)));
}

// A constant difference is its own interval, and every item is lower.
TEST(PairedComparison, AConstantDifferenceIsItsOwnInterval) {
  const std::vector<double> theirs{3, 5, 7, 9, 11, 2};
  std::vector<double> ours;
  for (const double v : theirs) ours.push_back(v - 0.5);
  const PairedComparison c = compare_paired(ours, theirs, 500);
  EXPECT_EQ(c.items, 6);
  EXPECT_EQ(c.lower, 6);
  EXPECT_EQ(c.ties, 0);
  EXPECT_DOUBLE_EQ(c.mean_difference, -0.5);
  EXPECT_DOUBLE_EQ(c.low, -0.5);
  EXPECT_DOUBLE_EQ(c.high, -0.5);
  EXPECT_DOUBLE_EQ(c.mean_ratio, 34.0 / 37.0);
  EXPECT_DOUBLE_EQ(c.sign_p, 2.0 / 64);
  const PairedComparison same = compare_paired(theirs, theirs);
  EXPECT_EQ(same.ties, 6);
  EXPECT_DOUBLE_EQ(same.sign_p, 1.0);
}

// Over random items: the interval holds the resampled means' range, lies
// within the smallest and largest difference, and is the same for the same seed.
RC_GTEST_PROP(PairedComparison, TheIntervalLiesWithinTheDifferences, ()) {
  const int n = *rc::gen::inRange(1, 40);
  std::vector<double> ours, theirs;
  double lo = 1e300, hi = -1e300;
  for (int i = 0; i < n; ++i) {
    ours.push_back(*rc::gen::inRange(0, 1000) / 100.0);
    theirs.push_back(*rc::gen::inRange(0, 1000) / 100.0);
    lo = std::min(lo, ours.back() - theirs.back());
    hi = std::max(hi, ours.back() - theirs.back());
  }
  const PairedComparison c = compare_paired(ours, theirs, 300, 0.9, 7);
  RC_ASSERT(c.low <= c.high);
  RC_ASSERT(c.low >= lo - 1e-12);
  RC_ASSERT(c.high <= hi + 1e-12);
  RC_ASSERT(c.lower + c.ties <= c.items);
  const PairedComparison again = compare_paired(ours, theirs, 300, 0.9, 7);
  RC_ASSERT(again.low == c.low && again.high == c.high);
}

TEST(PairedComparison, RefusesWhatItCannotCompare) {
  const std::vector<double> a{1, 2}, b{1};
  EXPECT_THROW(compare_paired(a, b), Error);
  EXPECT_THROW(compare_paired({}, {}), Error);
  const std::vector<double> nan{std::nan(""), 1};
  EXPECT_THROW(compare_paired(nan, a), Error);
  EXPECT_THROW(compare_paired(a, a, 0), ParameterError);
  EXPECT_THROW(compare_paired(a, a, 10, 1.0), ParameterError);
}

}  // namespace
}  // namespace aapat
