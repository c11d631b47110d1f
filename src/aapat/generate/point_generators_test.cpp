#include "aapat/generate/point_generators.h"
#include "aapat/generate/unit_random.h"
#include "testing/error_message.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <set>

namespace aapat {
namespace {

bool in_unit_square(const std::vector<Vec2>& p) {
  for (const Vec2& v : p)
    if (!(v.x >= 0 && v.x < 1 && v.y >= 0 && v.y < 1)) return false;
  return true;
}

RC_GTEST_PROP(Generators, NRooksHasOnePointPerRowAndColumn, ()) {
  const int n = *rc::gen::inRange(1, 200);
  const auto p = generate_points("n-rooks", n, *rc::gen::arbitrary<uint64_t>());
  std::set<int> rows, cols;
  for (const Vec2& v : p) {
    rows.insert(static_cast<int>(v.y * n));
    cols.insert(static_cast<int>(v.x * n));
  }
  RC_ASSERT(rows.size() == static_cast<size_t>(n));
  RC_ASSERT(cols.size() == static_cast<size_t>(n));
}

RC_GTEST_PROP(Generators, JitteredHasOnePointPerStratum, ()) {
  const int k = *rc::gen::inRange(1, 20);
  const auto p = generate_points("jittered", k * k, *rc::gen::arbitrary<uint64_t>());
  std::set<std::pair<int, int>> strata;
  for (const Vec2& v : p) strata.insert({static_cast<int>(v.x * k), static_cast<int>(v.y * k)});
  RC_ASSERT(strata.size() == static_cast<size_t>(k * k));
  RC_ASSERT(in_unit_square(p));
}

// Goss & Wu Table 6 sizes: no two queens share a row, column or diagonal.
TEST(Generators, NQueensAvoidRowsColumnsAndDiagonals) {
  for (int n : {4, 5, 8, 9, 16}) {
    const auto p = generate_points("n-queens", n, 0);
    ASSERT_EQ(static_cast<int>(p.size()), n);
    std::set<int> rows, cols, d1, d2;
    for (const Vec2& v : p) {
      const int c = static_cast<int>(v.x * n), r = static_cast<int>(v.y * n);
      EXPECT_NEAR(v.x, (c + 0.5) / n, 1e-12);  // cell centres
      rows.insert(r), cols.insert(c), d1.insert(r + c), d2.insert(r - c);
    }
    EXPECT_EQ(rows.size(), size_t(n));
    EXPECT_EQ(cols.size(), size_t(n));
    EXPECT_EQ(d1.size(), size_t(n));
    EXPECT_EQ(d2.size(), size_t(n));
  }
  EXPECT_EQ(n_queens_solutions(8, 1000000).size(), 92u);  // the classic count
  EXPECT_EQ(n_queens_solutions(4, 100).size(), 2u);
  EXPECT_THROW(generate_points("n-queens", 3, 0), Error);  // none for N = 3
}

RC_GTEST_PROP(Generators, PoissonDiskKeepsItsMinimumDistance, ()) {
  const int n = *rc::gen::inRange(2, 120);
  const double r = 0.6 * std::sqrt(2 / (std::sqrt(3.0) * n));
  const auto p =
      generate_points("poisson:radius=" + std::to_string(r), n, *rc::gen::arbitrary<uint64_t>());
  RC_ASSERT(p.size() == static_cast<size_t>(n));
  for (size_t i = 0; i < p.size(); ++i)
    for (size_t j = 0; j < i; ++j) {
      double dx = std::abs(p[i].x - p[j].x), dy = std::abs(p[i].y - p[j].y);
      dx = std::min(dx, 1 - dx), dy = std::min(dy, 1 - dy);  // on the torus
      RC_ASSERT(std::hypot(dx, dy) >= r * (1 - 1e-12));
    }
}

// Radical inverses (Pelikan): g_2(1) = 1/2, g_2(2) = 1/4, g_2(3) = 3/4, g_3(1) = 1/3, ...
TEST(Generators, HaltonAndHammersleyMatchTheRadicalInverse) {
  EXPECT_DOUBLE_EQ(radical_inverse(1, 2), 0.5);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 2), 0.25);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 2), 0.75);
  EXPECT_DOUBLE_EQ(radical_inverse(6, 2), 0.375);
  EXPECT_DOUBLE_EQ(radical_inverse(1, 3), 1.0 / 3);
  EXPECT_DOUBLE_EQ(radical_inverse(5, 3), 2.0 / 3 + 1.0 / 9);  // 5 = 12 in base 3
  const auto h = generate_points("halton", 4, 0);
  EXPECT_DOUBLE_EQ(h[2].x, 0.75);
  EXPECT_DOUBLE_EQ(h[2].y, 1.0 / 9);
  const auto m = generate_points("hammersley", 8, 0);
  EXPECT_DOUBLE_EQ(m[3].x, 3.0 / 8);
  EXPECT_DOUBLE_EQ(m[3].y, 0.75);
  EXPECT_DOUBLE_EQ(generate_points("halton:b1=3,b2=5", 2, 0)[1].y, 2.0 / 5);
}

// Larcher-Pillichshammer with x = i / 2^m is a (0, m, 2)-net: every
// elementary interval of area 2^-m holds exactly one point.
TEST(Generators, LarcherPillichshammerIsAZeroMTwoNet) {
  const int m = 8, n = 1 << m;
  const auto p = generate_points("larcher-pillichshammer", n, 0);
  for (int a = 0; a <= m; ++a) {
    std::set<std::pair<int, int>> cells;
    for (const Vec2& v : p)
      cells.insert({static_cast<int>(v.x * (1 << a)), static_cast<int>(v.y * (1 << (m - a)))});
    EXPECT_EQ(cells.size(), static_cast<size_t>(n)) << "intervals 2^-" << a << " x 2^-" << m - a;
  }
}

TEST(Generators, EveryGeneratorStaysInTheSquareAndIsDeterministic) {
  for (const auto& g : generator_registry().entries()) {
    const std::string& name = g.info.name;
    const int n = name == "n-queens" ? 8 : 64;
    const auto a = generate_points(name, n, 11), b = generate_points(name, n, 11);
    EXPECT_TRUE(in_unit_square(a)) << name;
    EXPECT_EQ(a, b) << name;
  }
}

TEST(Generators, BadSpecsAreNamed) {
  auto msg = [](const std::string& spec, int n) {
    return testing::error_message([&] { generate_points(spec, n, 0); });
  };
  EXPECT_EQ(msg("jitter", 4)
                .find("unknown generator 'jitter' (did you mean 'jittered'?): known "
                      "generators are regular, "),
            0u);
  EXPECT_EQ(msg("jittered", 5), "jittered: n = 5 must be a square number (k x k strata)");
  EXPECT_EQ(msg("halton:b1=4.5", 5), "generator halton: b1 = 4.5 must be a whole number in 2..64");
  EXPECT_EQ(msg("semi-jittered:amount=2", 4), "semi-jittered: amount = 2 is out of range [0, 1]");
  EXPECT_EQ(msg("random:q=1", 4),
            "generator random: unknown parameter 'q=1' (it takes no parameters)");
  EXPECT_EQ(msg("random", 0), "random: n = 0 is out of range 1..1000000");
  EXPECT_NE(
      msg("poisson:radius=0.5", 50).find("of 50 points fit at radius 0.5; use a smaller radius"),
      std::string::npos);
}

// Realizations are work items: set r is generate_points with seed + r, the
// same on one thread as on all, and progress hears of each.
TEST(Generators, PointSetsAreTheSeededSetsOnAnyThreadCount) {
  int calls = 0, last_total = 0;
  const auto all =
      generate_point_sets("poisson", 50, 7, 12, [&](int, int total, const std::string& note) {
        ++calls;
        last_total = total;
        EXPECT_EQ(note, "");  // a count, not the set's bytes
      });
  ASSERT_EQ(all.size(), 12u);
  EXPECT_EQ(calls, 12);
  EXPECT_EQ(last_total, 12);
  for (size_t r = 0; r < all.size(); ++r) EXPECT_EQ(all[r], generate_points("poisson", 50, 7 + r));
  tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
  EXPECT_EQ(generate_point_sets("poisson", 50, 7, 12), all);
}

TEST(Generators, PointSetsKeepToTheirLimits) {
  EXPECT_EQ(testing::error_parameter([] { generate_point_sets("random", 1000, 1, 0); }), "sets");
  EXPECT_EQ(testing::error_parameter([] { generate_point_sets("random", 1000, 1, 100001); }),
            "sets");
  EXPECT_EQ(testing::error_message([] { generate_point_sets("random", 1000000, 1, 51); }),
            "sets 51 of 1000000 points each: 51000000 points in all, over the limit of 50000000 "
            "(16 bytes each in memory)");
}

// The slow generators tell their progress in rising hundredths, and the
// same points with or without a listener.
TEST(Generators, SlowGeneratorsReportHundredthsOfTheSamePoints) {
  for (const char* spec : {"poisson", "best-candidate", "poisson-maximal"}) {
    std::vector<int> done;
    const auto p = generate_points(spec, 500, 3, [&](int d, int total, const std::string&) {
      EXPECT_EQ(total, 100);
      done.push_back(d);
    });
    EXPECT_EQ(p, generate_points(spec, 500, 3)) << spec;
    ASSERT_FALSE(done.empty()) << spec;
    EXPECT_TRUE(std::is_sorted(done.begin(), done.end())) << spec;
    EXPECT_EQ(std::adjacent_find(done.begin(), done.end()), done.end()) << spec;  // no repeats
    EXPECT_GE(done.back(), 95) << spec;
  }
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

// unit_double is std::uniform_real_distribution<double>(0, 1), bit for bit:
// on the draws where rounding x / 2^64 is hardest (ties, the top values that
// round to 1) and on random ones.
struct FixedDraw {  // a 64-bit generator that returns one value
  using result_type = uint64_t;
  static constexpr uint64_t min() { return 0; }
  static constexpr uint64_t max() { return ~uint64_t{0}; }
  uint64_t x;
  uint64_t operator()() const { return x; }
};
TEST(Generators, UnitDoubleIsTheStandardDistributionsDraw) {
  std::vector<uint64_t> xs = {0,
                              1,
                              (uint64_t{1} << 53) - 1,
                              (uint64_t{1} << 53) + 1,
                              (uint64_t{1} << 63) - 1,
                              uint64_t{1} << 63,
                              (uint64_t{1} << 63) + 1024,  // a tie, to even
                              (uint64_t{1} << 63) + 3072,  // a tie, to even (up)
                              ~uint64_t{0},
                              ~uint64_t{0} - 1023,
                              ~uint64_t{0} - 1024,
                              ~uint64_t{0} - 2048};
  std::mt19937_64 rng(20261204);
  for (int i = 0; i < 100000; ++i) xs.push_back(rng());
  for (const uint64_t x : xs) {
    FixedDraw g{x};
    std::uniform_real_distribution<double> u(0, 1);
    const double standard = u(g), ours = unit_double_of(x);
    EXPECT_EQ(std::memcmp(&standard, &ours, sizeof(double)), 0) << x;
    EXPECT_LT(ours, 1.0) << x;
  }
}

// Jittered points are (i + u) / k with u the standard distribution's draws,
// bit for bit, whether k is a power of two (multiplied by 1 / k) or not.
TEST(Generators, JitteredIsTheStandardDrawOverK) {
  for (const int k : {1, 3, 4, 5, 32}) {
    const uint64_t seed = 40 + static_cast<uint64_t>(k);
    const std::vector<Vec2> points = generate_points("jittered", k * k, seed);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    ASSERT_EQ(points.size(), static_cast<size_t>(k * k));
    for (int j = 0, at = 0; j < k; ++j)
      for (int i = 0; i < k; ++i, ++at) {
        const double x = (i + u(rng)) / k, y = (j + u(rng)) / k;
        EXPECT_EQ(points[static_cast<size_t>(at)].x, x) << k << " " << at;
        EXPECT_EQ(points[static_cast<size_t>(at)].y, y) << k << " " << at;
      }
  }
}

// The grid search finds the same farthest candidates as a plain search over
// every point (same random stream, same points).
RC_GTEST_PROP(Generators, BestCandidateMatchesBruteForce, ()) {
  const int n = *rc::gen::inRange(1, 80);
  const uint64_t seed = *rc::gen::arbitrary<uint64_t>();
  const auto fast = generate_points("best-candidate:q=3", n, seed);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  auto dist = [](Vec2 a, Vec2 b) {
    double dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
    return std::hypot(std::min(dx, 1 - dx), std::min(dy, 1 - dy));
  };
  std::vector<Vec2> slow;
  for (int i = 0; i < n; ++i) {
    auto nearest = [&](Vec2 c) {
      double d = INFINITY;
      for (const Vec2& e : slow) d = std::min(d, dist(e, c));
      return i > 0 ? d : 0.0;
    };
    Vec2 best{u(rng), u(rng)};
    double best_d = nearest(best);
    for (int t = 1; t < std::max(1, 3 * i); ++t) {
      const Vec2 c{u(rng), u(rng)};
      if (nearest(c) > best_d) best_d = nearest(c), best = c;
    }
    slow.push_back(best);
  }
  RC_ASSERT(fast == slow);
}

}  // namespace
}  // namespace aapat

namespace aapat {
namespace {

TEST(Generators, PixelPointsDependOnlyOnSeedAndPixel) {
  const auto a = pixel_points("jittered", 4, 7, 10, 3);
  EXPECT_EQ(a, pixel_points("jittered", 4, 7, 10, 3));
  EXPECT_NE(a, pixel_points("jittered", 4, 7, 3, 10));
  EXPECT_NE(a, pixel_points("jittered", 4, 8, 10, 3));
  for (const Vec2& v : a) EXPECT_TRUE(v.x >= -0.5 && v.x < 0.5 && v.y >= -0.5 && v.y < 0.5);
}

TEST(Generators, TilePatternIsAValidPs1n) {
  const Pattern p = tile_pattern("n-rooks", 3, 5, 2);
  EXPECT_NO_THROW(validate(p));
  EXPECT_EQ(family(p), "P(4,1,3)");
  EXPECT_EQ(p.sets[1], pixel_points("n-rooks", 3, 5, 1, 0));
  EXPECT_THROW(tile_pattern("n-rooks", 3, 5, 0), Error);
}

}  // namespace
}  // namespace aapat
