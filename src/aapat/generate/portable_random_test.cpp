#include "aapat/generate/portable_random.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

namespace aapat {
namespace {

// The first draws for seed 1, the same with every standard library: what
// libstdc++'s distributions draw (checked below where it is the library).
TEST(PortableRandom, KnownDrawsForSeedOne) {
  std::mt19937_64 rng(1);
  std::vector<int64_t> dice;
  for (int i = 0; i < 8; ++i) dice.push_back(uniform_int(rng, 1, 6));
  std::vector<int> perm(10);
  std::iota(perm.begin(), perm.end(), 0);
  shuffle(perm.begin(), perm.end(), rng);
  // Every value in range and a permutation: the properties that hold anywhere.
  for (int64_t d : dice) EXPECT_TRUE(d >= 1 && d <= 6);
  std::vector<int> sorted = perm;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < 10; ++i) EXPECT_EQ(sorted[i], i);
  EXPECT_EQ(dice, (std::vector<int64_t>{1, 1, 3, 1, 3, 6, 3, 1}));
  EXPECT_EQ(perm, (std::vector<int>{4, 9, 5, 6, 0, 1, 3, 8, 7, 2}));
}

#if defined(__GLIBCXX__)
// Under libstdc++, the same draws as its distributions, for many seeds, sizes
// and ranges: aapat's native outputs did not change.
TEST(PortableRandom, TheSameDrawsAsLibstdcxx) {
  for (uint64_t seed = 0; seed < 200; ++seed) {
    std::mt19937_64 a(seed), b(seed);
    for (uint64_t n : {1ull, 2ull, 3ull, 7ull, 1000ull, (1ull << 40) + 3, ~0ull / 3}) {
      std::uniform_int_distribution<uint64_t> d(0, n - 1);
      ASSERT_EQ(uniform_below(a, n), d(b));
    }
    std::uniform_int_distribution<int> dice(-3, 9);
    ASSERT_EQ(uniform_int(a, -3, 9), dice(b));
    std::uniform_real_distribution<double> u(-0.25, 0.75);
    ASSERT_EQ(uniform_real(a, -0.25, 0.75), u(b));
    std::bernoulli_distribution coin(0.45);
    ASSERT_EQ(bernoulli(a, 0.45), coin(b));
    for (int n : {1, 2, 5, 64, 513}) {
      std::vector<int> x(n), y(n);
      std::iota(x.begin(), x.end(), 0);
      std::iota(y.begin(), y.end(), 0);
      shuffle(x.begin(), x.end(), a);
      std::shuffle(y.begin(), y.end(), b);
      ASSERT_EQ(x, y) << "seed " << seed << ", n " << n;
    }
    Gaussian g(0.5, 2);
    std::normal_distribution<double> normal(0.5, 2);
    for (int i = 0; i < 5; ++i) ASSERT_NEAR(g(a), normal(b), 1e-12);
    ASSERT_EQ(a(), b());  // the same number of engine draws
  }
}
#endif

// The integer draw is uniform: counts over 7 values within 5 standard
// deviations of n / 7.
TEST(PortableRandom, UniformBelowIsUniform) {
  std::mt19937_64 rng(3);
  std::vector<int> counts(7);
  const int n = 70000;
  for (int i = 0; i < n; ++i) ++counts[uniform_below(rng, 7)];
  for (int c : counts) EXPECT_NEAR(c, n / 7.0, 5 * std::sqrt(n * (1 / 7.0) * (6 / 7.0)));
}

}  // namespace
}  // namespace aapat
