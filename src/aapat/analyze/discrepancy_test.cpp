#include "aapat/analyze/discrepancy.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <random>

#include "testing/random_points.h"

#include "aapat/analyze/double_double.h"

namespace aapat {
namespace {

using testing::random_points;

// Warnock's closed form against numerical integration of the local
// discrepancy squared over all anchored boxes.
// Warnock's sum exactly, for coordinates on the 1/1024 grid: 9 N^2 2^42 T^2
// is the integer N^2 2^42 - 18 N sum_i (2^20 - a_i^2)(2^20 - b_i^2)
// + 9 2^22 sum_ij (1024 - max a)(1024 - max b), with x = a / 1024, y = b / 1024.
double exact_l2_star_squared(const std::vector<std::pair<int, int>>& ab) {
  __extension__ typedef __int128 I;  // exact: the sums stay below 2^100
  const I n = static_cast<I>(ab.size());
  I single = 0, pairs = 0;
  for (const auto& [a, b] : ab) {
    single += ((I(1) << 20) - I(a) * a) * ((I(1) << 20) - I(b) * b);
    for (const auto& [c, d] : ab) pairs += I(1024 - std::max(a, c)) * (1024 - std::max(b, d));
  }
  const I t = n * n * (I(1) << 42) - 18 * n * single + 9 * (I(1) << 22) * pairs;
  return static_cast<double>(t) / (9.0 * static_cast<double>(n * n) * std::ldexp(1.0, 42));
}

RC_GTEST_PROP(L2StarDiscrepancy, AgreesWithExactArithmeticTo1e12, ()) {
  const int n = *rc::gen::inRange(1, 200);
  std::vector<std::pair<int, int>> ab;
  std::vector<Vec2> p;
  for (int i = 0; i < n; ++i) {
    // Often on a coarse grid, so that ties in x and in y are common.
    const int step = *rc::gen::element(1, 64);
    const int a = *rc::gen::inRange(0, 1025 / step) * step,
              b = *rc::gen::inRange(0, 1025 / step) * step;
    ab.push_back({a, b});
    p.push_back({a / 1024.0, b / 1024.0});
  }
  const double exact = exact_l2_star_squared(ab), got = l2_star_discrepancy(p);
  RC_ASSERT(std::abs(got * got - exact) <= 1e-12 * exact);
}

// Warnock's O(N^2) sum in double-double: a check of the O(N log N) sweep on
// sets too large for exact arithmetic, where one double loses the result.
double l2_star_squared_pairwise(const std::vector<Vec2>& p) {
  DoubleDouble single, pairs;
  for (const Vec2& u : p) {
    single += (DoubleDouble(1) - two_prod(u.x, u.x)) * (DoubleDouble(1) - two_prod(u.y, u.y));
    for (const Vec2& v : p)
      pairs += (DoubleDouble(1) - std::max(u.x, v.x)) * (DoubleDouble(1) - std::max(u.y, v.y));
  }
  const double n = static_cast<double>(p.size());
  const DoubleDouble ninth(1.0 / 9, std::fma(-9.0, 1.0 / 9, 1.0) / 9);
  return (ninth - single / (2 * n) + pairs / n / n).value();
}

TEST(L2StarDiscrepancy, TheSweepAgreesWithTheCompensatedPairSum) {
  std::vector<Vec2> halton;
  for (uint64_t i = 1; i <= 3000; ++i) {
    auto inverse = [](uint64_t k, int b) {
      double f = 1.0 / b, r = 0;
      for (; k; k /= b, f /= b) r += f * static_cast<double>(k % b);
      return r;
    };
    halton.push_back({inverse(i, 2), inverse(i, 3)});
  }
  for (const auto& p : {random_points(5, 2500), halton}) {
    const double reference = l2_star_squared_pairwise(p), got = l2_star_discrepancy(p);
    EXPECT_NEAR(got * got, reference, 1e-12 * reference);
  }
}

// The unit square clipped by p . n <= t (Sutherland-Hodgman, one plane) and
// the polygon's area: the reference for the closed form.
double clipped_area(double phi, double t) {
  const double c = std::cos(phi), s = std::sin(phi);
  const Vec2 square[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Vec2 out[8];
  int m = 0;
  for (int i = 0; i < 4; ++i) {
    const Vec2 a = square[i], b = square[(i + 1) % 4];
    const double da = a.x * c + a.y * s - t, db = b.x * c + b.y * s - t;
    if (da <= 0) out[m++] = a;
    if ((da < 0) != (db < 0) && da != db) {
      const double u = da / (da - db);
      out[m++] = {a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)};
    }
  }
  double area = 0;
  for (int i = 0; i < m; ++i) area += out[i].x * out[(i + 1) % m].y - out[(i + 1) % m].x * out[i].y;
  return std::abs(area) / 2;
}

RC_GTEST_PROP(EdgeDiscrepancy, TheClosedFormAreaEqualsThePolygonClip, ()) {
  const double phi = *rc::gen::inRange(-3600, 3601) * kPi / 1800;  // every quadrant, the axes
  const double t = *rc::gen::inRange(-1500, 1501) / 1000.0;
  RC_ASSERT(std::abs(half_plane_area(phi, t) - clipped_area(phi, t)) <= 1e-12);
}

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
