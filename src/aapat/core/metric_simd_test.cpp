#include "aapat/core/metric_simd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <random>

#include "aapat/core/filter_catalog.h"
#include "aapat/core/metric.h"
#include "testing/every_simd_path.h"

namespace aapat {
namespace {

using testing::EveryPath;

// n samples with weights, in [-extent, extent]^2.
Kernel random_kernel(std::mt19937_64& rng, size_t n, double extent) {
  std::uniform_real_distribution<double> u(-extent, extent), w(0.1, 1);
  std::vector<Vec2> s(n);
  std::vector<double> weights(n);
  double total = 0;
  for (size_t i = 0; i < n; ++i) {
    s[i] = {u(rng), u(rng)};
    total += weights[i] = w(rng);
  }
  for (double& v : weights) v /= total;
  return make_kernel(s, weights);
}

// The scalar reference: e1_squared's closed form angle by angle, through
// Filter::abs_moment, as the metric computed before it was vectorized.
std::vector<double> scalar_terms(const Metric& m, const Kernel& k) {
  const size_t n = k.w.size();
  std::vector<double> p(n), values(m.angle_count());
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const bool dense = n > kPairwiseLimit && m.angle_count() >= kDenseAngles;
  for (int a = 0; a < m.angle_count(); ++a) {
    for (size_t j = 0; j < n; ++j) p[j] = m.cos(a) * k.y[j] - m.sin(a) * k.x[j];
    if (dense && a == 0)
      std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
    else if (dense)
      sort_by_projection(order, p);
    values[a] = m.weight_sq(a) * (dense ? e1_squared_in_order(m.filter(), p, k.w, order)
                                        : e1_squared(m.filter(), p, k.w));
  }
  return values;
}

// The vectorized metric gives the scalar code's bits, on every path, for every
// filter of the registry, small kernels (pair form, lanes over angles) and
// large ones (lanes over samples), sparse and dense acuity tables (the latter
// 258 angles: a partial last block on every vector width). Samples over
// three pixels reach every piece of J; samples inside one pixel stay in the
// first piece of Mitchell-Netravali's (1 wide), the vector path's shortcut.
TEST(MetricSimd, EveryPathGivesTheScalarBitsForEveryFilter) {
  std::mt19937_64 rng(5);
  EveryPath paths;
  for (const auto& entry : filter_registry().entries()) {
    const Filter filter = make_filter(entry.info.name);
    for (const char* acuity : {"laine-aila", "uniform:step=0.7"}) {
      const Metric metric(filter, make_acuity(acuity));
      for (const size_t n : {size_t{1}, size_t{2}, size_t{4}, size_t{7}, kPairwiseLimit,
                             kPairwiseLimit + 1, size_t{64}})
        for (const double extent : {1.5, 0.5}) {
          const Kernel k = random_kernel(rng, n, extent);
          const std::vector<double> reference = scalar_terms(metric, k);
          paths.run([&] {
            const std::vector<double> profile = metric.profile(k);
            ASSERT_EQ(profile.size(), reference.size());
            for (size_t a = 0; a < profile.size(); ++a)
              ASSERT_EQ(profile[a], std::sqrt(reference[a]))
                  << entry.info.name << " " << acuity << " n " << n << " extent " << extent
                  << " angle " << a;
          });
        }
    }
  }
}

// J at many points at once: the pieces' boundaries, the radius, past it,
// both signs, zero, and NaN; lengths that leave a partial last block.
TEST(MetricSimd, AbsMomentsAreFilterAbsMomentBitForBit) {
  EveryPath paths;
  for (const char* spec : {"box", "tent", "mitchell", "gaussian", "lanczos:lobes=3"}) {
    const Filter f = make_filter(spec);
    const Filter::AbsMomentTable t = f.abs_moment_table();
    std::vector<double> p;
    for (int k = 0; k <= t.segments; ++k)
      for (const double d : {-1e-12, 0.0, 1e-12}) p.push_back(k * t.width + d);
    // Whole vectors either side of the end of the first piece, where the
    // vector path's first-piece shortcut stops (width (1 - 4 eps)), either sign.
    const double eps = std::numeric_limits<double>::epsilon();
    for (const double edge : {t.width * (1 - 8 * eps), t.width * (1 - 4 * eps),
                              t.width * (1 - 3 * eps), std::nextafter(t.width, 0.0), t.width,
                              std::nextafter(t.width, 2 * t.width), t.width * (1 + 4 * eps)})
      for (int copy = 0; copy < 8; ++copy) p.push_back(copy % 2 ? -edge : edge);
    for (int i = 0; i < 200; ++i) p.push_back(-3 * f.radius() + 6 * f.radius() * i / 199.0);
    p.push_back(0.0);
    p.push_back(-0.0);
    p.push_back(std::numeric_limits<double>::quiet_NaN());
    p.push_back(std::numeric_limits<double>::infinity());
    paths.run([&] {
      for (size_t length : {p.size(), p.size() - 1, size_t{3}}) {
        std::vector<double> out(length);
        abs_moments(t, p.data(), length, out.data());
        for (size_t i = 0; i < length; ++i) {
          const double expected = f.abs_moment(p[i]);
          if (std::isnan(expected))
            EXPECT_TRUE(std::isnan(out[i])) << spec << " p " << p[i];
          else
            EXPECT_EQ(out[i], expected) << spec << " p " << p[i];
        }
      }
    });
  }
}

// Step responses: Filter::step_response's bits on every path, for every
// filter of the registry, at the pieces' ends (and an ulp either side), on
// both sides of zero, at and past the radius, and between.
TEST(MetricSimd, StepResponsesAreFilterStepResponseBitForBit) {
  EveryPath paths;
  for (const auto& entry : filter_registry().entries()) {
    const Filter f = make_filter(entry.info.name);
    const Filter::AbsMomentTable t = f.step_response_table();
    std::vector<double> p;
    for (int k = 0; k <= t.segments; ++k)
      for (const double sign : {-1.0, 1.0}) {
        const double at = sign * k * t.width;
        p.insert(p.end(), {at, std::nextafter(at, -HUGE_VAL), std::nextafter(at, HUGE_VAL)});
      }
    for (int i = 0; i < 301; ++i) p.push_back(-1.5 * f.radius() + 3 * f.radius() * i / 300.0);
    p.insert(p.end(), {0.0, -0.0, f.radius(), -f.radius(), HUGE_VAL, -HUGE_VAL});
    paths.run([&] {
      for (size_t length : {p.size(), p.size() - 1, size_t{3}}) {
        std::vector<double> out(length);
        step_responses(f, p.data(), length, out.data());
        for (size_t i = 0; i < length; ++i) {
          const double expected = f.step_response(p[i]);
          EXPECT_EQ(std::memcmp(&out[i], &expected, sizeof expected), 0)
              << entry.info.name << " a " << p[i] << ": " << out[i] << " against " << expected;
        }
      }
    });
  }
}

// The gradient's pair sums: the scalar loop's bits on every path, ties (sign
// 0) and negative weights included, for every size of the pair form.
TEST(MetricSimd, PairSumsAreTheScalarLoopsBitForBit) {
  EveryPath paths;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (size_t n = 1; n <= kPairwiseLimit; ++n) {
    std::vector<double> p(n), w(n);
    for (size_t j = 0; j < n; ++j) {
      p[j] = j % 5 == 4 ? p[j - 1] : u(rng);  // some ties
      w[j] = u(rng);
    }
    std::vector<double> balance(kPairwiseLimit, 0.0), spread(kPairwiseLimit, 0.0);
    for (size_t k = 0; k < n; ++k)
      for (size_t j = 0; j < n; ++j) {
        const double d = p[j] - p[k];
        balance[j] += d > 0 ? w[k] : d < 0 ? -w[k] : 0.0;
        spread[j] += w[k] * std::abs(d);
      }
    paths.run([&] {
      std::vector<double> b(kPairwiseLimit), s(kPairwiseLimit);
      pairwise_balance_spread(p.data(), w.data(), n, b.data(), s.data());
      for (size_t j = 0; j < n; ++j) {
        EXPECT_EQ(b[j], balance[j]) << n << " " << j;
        EXPECT_EQ(s[j], spread[j]) << n << " " << j;
      }
    });
  }
}

// largest_or_zero is std::max from 0 over the values in order, on every
// path and length (partial vectors, fewer values than a vector), with NaN,
// infinities, negatives and both zeros among them.
TEST(MetricSimd, LargestOrZeroIsStdMaxFromZero) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> kind(0, 9);
  EveryPath paths;
  for (size_t n = 0; n <= 70; ++n)
    for (int trial = 0; trial < 4; ++trial) {
      std::vector<double> v(n);
      for (double& x : v) {
        const int k = kind(rng);
        x = k == 0       ? std::numeric_limits<double>::quiet_NaN()
            : k == 1     ? (trial == 3 ? std::numeric_limits<double>::infinity() : -0.0)
            : trial == 2 ? -std::abs(u(rng))
                         : u(rng);
      }
      double expected = 0;
      for (const double x : v) expected = std::max(expected, x);
      paths.run([&] {
        const double got = largest_or_zero(v);
        EXPECT_EQ(got, expected) << "n " << n << " trial " << trial;
        EXPECT_FALSE(std::signbit(got)) << "n " << n << " trial " << trial;
      });
    }
}

TEST(MetricSimd, NamesThePathItRuns) {
  const std::vector<int64_t> targets = simd_targets_here();
  ASSERT_FALSE(targets.empty());
  EXPECT_EQ(simd_target(), simd_target_name(targets.front()));
}

}  // namespace
}  // namespace aapat
