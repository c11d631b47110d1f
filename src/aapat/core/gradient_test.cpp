#include "aapat/core/gradient.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"

namespace aapat {
namespace {

// Every gradient component against a central difference, for every filter,
// on random 1D patterns with signed weights summing to 1. Samples keep apart
// by more than the difference step, so no two cross (where E1 has a kink).
RC_GTEST_PROP(E1Gradient, MatchesCentralDifferences, ()) {
  const auto& catalog = filter_registry().entries();
  const Filter f = make_filter(catalog[*rc::gen::inRange<size_t>(0, catalog.size())].info.name);
  const int n = *rc::gen::inRange(1, 34);  // both sides of the pairwise/sorted switch
  std::vector<double> p(n), w(n);
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    p[i] = *rc::gen::inRange(-2500, 2501) / 1000.0 + i * 1e-5;
    w[i] = *rc::gen::inRange(-300, 1001) / 1000.0;
    sum += w[i];
  }
  RC_PRE(std::abs(sum) > 0.1);
  for (double& v : w) v /= sum;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < i; ++j) RC_PRE(std::abs(p[i] - p[j]) > 1e-4);
  std::vector<double> dp(n), dw(n);
  const double value = e1_squared_gradient(f, p, w, dp, dw);
  RC_ASSERT(std::abs(value - e1_squared(f, p, w)) <= 1e-12);
  const double h = 1e-6;
  for (int i = 0; i < n; ++i) {
    auto at = [&](double dpi) {
      std::vector<double> q = p;
      q[i] += dpi;
      return e1_squared(f, q, w);
    };
    const double fd = (at(h) - at(-h)) / (2 * h);
    RC_ASSERT(std::abs(fd - dp[i]) <= 1e-6 * std::max(1.0, std::abs(fd)));
  }
  // Weights move along the plane sum w = 1: w_i + h, w_0 - h.
  for (int i = 1; i < n; ++i) {
    auto at = [&](double d) {
      std::vector<double> v = w;
      v[i] += d;
      v[0] -= d;
      return e1_squared(f, p, v);
    };
    const double fd = (at(h) - at(-h)) / (2 * h);
    RC_ASSERT(std::abs(fd - (dw[i] - dw[0])) <= 1e-6 * std::max(1.0, std::abs(fd)));
  }
}

// Laine-Aila Eq. 6, read on E1^2: dE1^2/dp_i = w_i (2 g0(p_i) - 2 sum_{p_j < p_i} w_j - w_i).
TEST(E1Gradient, AgreesWithLaineAilaEquation6) {
  const Filter f = make_filter("mitchell");
  const std::vector<double> p = {-0.4, 0.05, 0.3, 0.9}, w = {0.2, 0.35, 0.3, 0.15};
  std::vector<double> dp(4), dw(4);
  e1_squared_gradient(f, p, w, dp, dw);
  double below = 0;
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(dp[i], w[i] * (2 * f.step_response(p[i]) - 2 * below - w[i]), 1e-14);
    below += w[i];
  }
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

// Re-sorting from any permutation gives sort_samples's order, ties and NaN
// included (where std::sort's order among equals is the one kept).
RC_GTEST_PROP(SortSamples, ResortingFromAnyOrderIsSortingAfresh, ()) {
  const size_t n = *rc::gen::inRange<size_t>(0, 40);
  std::vector<double> p;
  for (size_t j = 0; j < n; ++j) {
    const int kind = *rc::gen::inRange(0, 10);
    p.push_back(kind == 0 && j > 0 ? p[*rc::gen::inRange<size_t>(0, j)]
                : kind == 1        ? std::nan("")
                                   : *rc::gen::inRange(-1000, 1000) / 997.0);
  }
  std::vector<size_t> order(n), want;
  std::iota(order.begin(), order.end(), 0);
  for (size_t i = n; i > 1; --i) std::swap(order[i - 1], order[*rc::gen::inRange<size_t>(0, i)]);
  if (*rc::gen::inRange(0, 4) == 0) order.clear();  // no order yet
  resort_samples(p, order);
  sort_samples(p, want);
  RC_ASSERT(order == want);
}

}  // namespace
}  // namespace aapat
