#include "aapat/analyze/discrepancy.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <random>

namespace aapat {
namespace {

std::vector<Vec2> random_points(uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec2> p(n);
  for (auto& v : p) v = {u(rng), u(rng)};
  return p;
}

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

// Warnock's closed form against numerical integration of the local
// discrepancy squared over all anchored boxes.
TEST(L2StarDiscrepancy, MatchesNumericalIntegration) {
  for (uint64_t seed : {1, 2, 3}) {
    const auto p = random_points(seed, 7);
    const int m = 2000;
    double sum = 0;
    for (int i = 0; i < m; ++i)
      for (int j = 0; j < m; ++j) {
        const double a = (i + 0.5) / m, b = (j + 0.5) / m;
        int inside = 0;
        for (const Vec2& v : p) inside += v.x < a && v.y < b;
        const double d = double(inside) / p.size() - a * b;
        sum += d * d;
      }
    EXPECT_NEAR(l2_star_discrepancy(p), std::sqrt(sum / (double(m) * m)), 2e-4);
  }
  // One point at the origin: T^2 = 1/9 - 2/4 + 1 ... = 1/9 - 1/2 + 1.
  EXPECT_NEAR(l2_star_discrepancy({{0, 0}}), std::sqrt(1.0 / 9 - 0.5 + 1), 1e-15);
}

TEST(EdgeDiscrepancy, HalfPlaneAreaAndSimpleSets) {
  EXPECT_NEAR(half_plane_area(0, 0.3), 0.3, 1e-15);
  EXPECT_NEAR(half_plane_area(kPi / 2, 0.25), 0.25, 1e-15);
  EXPECT_NEAR(half_plane_area(kPi / 4, std::sqrt(0.5)), 0.5, 1e-15);
  EXPECT_NEAR(half_plane_area(kPi / 4, std::sqrt(0.5) / 2), 0.125, 1e-15);
  EXPECT_NEAR(half_plane_area(0, 2), 1.0, 1e-15);
  // One point at the centre: a half-plane through it, with or without it, is off by 1/2.
  EXPECT_NEAR(edge_discrepancy({{0.5, 0.5}}).value, 0.5, 1e-12);
}

// The edge discrepancy bounds the discrepancy of every axis-aligned
// half-plane, which a direct count checks.
RC_GTEST_PROP(EdgeDiscrepancy, AtLeastEveryVerticalHalfPlane, ()) {
  const auto p = random_points(*rc::gen::arbitrary<uint64_t>(), *rc::gen::inRange(1, 30));
  const double edge = edge_discrepancy(p, 180).value;
  for (const Vec2& v : p) {
    int left = 0;
    for (const Vec2& q : p) left += q.x <= v.x;
    RC_ASSERT(edge + 1e-12 >= std::abs(v.x - double(left) / p.size()));
  }
}

}  // namespace
}  // namespace aapat
