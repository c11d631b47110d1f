#include "aapat/core/portable_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>

namespace aapat {
namespace {

// Distance in units in the last place between two finite doubles of one sign.
int64_t ulps(double a, double b) {
  int64_t ia = 0, ib = 0;
  std::memcpy(&ia, &a, sizeof a);
  std::memcpy(&ib, &b, sizeof b);
  return ia > ib ? ia - ib : ib - ia;
}

TEST(PortableMath, ExactValuesAndIdentities) {
  EXPECT_EQ(portable_sin(0.0), 0.0);
  EXPECT_TRUE(std::signbit(portable_sin(-0.0)));
  EXPECT_EQ(portable_cos(0.0), 1.0);
  EXPECT_EQ(portable_exp(0.0), 1.0);
  EXPECT_EQ(portable_log(1.0), 0.0);
  EXPECT_EQ(portable_pow(2.0, 10.0), 1024.0);
  EXPECT_EQ(portable_pow(9.0, 0.5), 3.0);
  EXPECT_EQ(portable_pow(-2.0, 3.0), -8.0);
  EXPECT_EQ(portable_exp(1.0), 0x1.5bf0a8b145769p+1);  // e, correctly rounded
  EXPECT_EQ(portable_log(2.0), 0x1.62e42fefa39efp-1);  // log 2, correctly rounded
  // sin of the double nearest pi/6 is just below 1/2: 0.49999999999999994.
  EXPECT_EQ(portable_sin(0x1.0c152382d7365p-1), 0x1.fffffffffffffp-2);
  // cos of the double nearest pi/2 is pi/2's rounding error, 6.123e-17.
  EXPECT_EQ(portable_cos(0x1.921fb54442d18p+0), 0x1.1a62633145c07p-54);
  EXPECT_TRUE(std::isnan(portable_log(-1.0)));
  EXPECT_TRUE(std::isinf(portable_exp(710.0)));
  EXPECT_EQ(portable_exp(-746.0), 0.0);
}

// Against the C library over random arguments: never more than one unit in
// the last place apart (the C library's own error bound), and equal in almost
// every case, as a correctly rounded result should be.
TEST(PortableMath, WithinOneUlpOfTheCLibrary) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(-20, 20), exponent(-700, 700), positive(-300, 300);
  int equal = 0, total = 0;
  for (int i = 0; i < 20000; ++i) {
    const double a = angle(rng), e = exponent(rng), l = std::pow(10.0, positive(rng));
    const double p = std::abs(angle(rng)) + 1e-3, q = angle(rng) / 4;
    const std::pair<double, double> pairs[] = {{portable_sin(a), std::sin(a)},
                                               {portable_cos(a), std::cos(a)},
                                               {portable_exp(e), std::exp(e)},
                                               {portable_log(l), std::log(l)},
                                               {portable_pow(p, q), std::pow(p, q)}};
    for (const auto& [mine, libm] : pairs) {
      ASSERT_LE(ulps(mine, libm), 1) << mine << " " << libm << " at step " << i;
      equal += mine == libm;
      ++total;
    }
  }
  EXPECT_GE(equal, total * 999 / 1000) << equal << " of " << total;
}

// The fast forms: within two units in the last place of the C library.
TEST(PortableMath, FastExpAndLogWithinTwoUlps) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> exponent(-700, 700), power(-300, 300);
  for (int i = 0; i < 20000; ++i) {
    const double e = exponent(rng), l = std::pow(10.0, power(rng));
    ASSERT_LE(ulps(portable_exp_fast(e), std::exp(e)), 2) << e;
    ASSERT_LE(ulps(portable_log_fast(l), std::log(l)), 2) << l;
  }
  EXPECT_EQ(portable_exp_fast(0.0), 1.0);
  EXPECT_EQ(portable_log_fast(1.0), 0.0);
}

TEST(PortableMath, PythagoreanIdentityToTheLastBits) {
  for (int d = 0; d < 720; ++d) {
    const double x = d * 0x1.921fb54442d18p+0 / 90;
    const double s = portable_sin(x), c = portable_cos(x);
    EXPECT_NEAR(s * s + c * c, 1.0, 4e-16) << d;
  }
}

}  // namespace
}  // namespace aapat
