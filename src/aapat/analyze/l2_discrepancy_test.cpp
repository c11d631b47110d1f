#include "aapat/analyze/l2_discrepancy.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "aapat/analyze/discrepancy.h"
#include "aapat/analyze/double_double.h"

namespace aapat {
namespace {

__extension__ typedef __int128 Int;

// Each discrepancy as Hickernell 1998 (and Warnock 1972 for the star) write
// it, for coordinates a / 1024 with integer a: every per-coordinate term is an
// integer over F = 12 * 2^20, so D^2 N^2 F^2 is an integer, summed exactly
// over all pairs. The forms use |u - v| and max, not the min that the fast
// sums are built on.
constexpr Int kF = Int(12) << 20;
struct ExactForm {
  std::function<Int(Int, Int)> pair;  // F * the pair factor of coordinates a, c
  std::function<Int(Int)> single;     // F * the single-point factor
  Int constant;                       // F * the constant factor
};
Int abs_int(Int v) {
  return v < 0 ? -v : v;
}
ExactForm exact_form(L2Kind kind) {
  switch (kind) {
    case L2Kind::star:  // 1 - max(u, v); (1 - u^2) / 2; 1/3
      return {[](Int a, Int c) { return (1024 - std::max(a, c)) * 12 * 1024; },
              [](Int a) { return ((Int(1) << 20) - a * a) * 6; }, Int(4) << 20};
    case L2Kind::generalized:  // 2 - max(u, v); (3 - u^2) / 2; 4/3
      return {[](Int a, Int c) { return (2048 - std::max(a, c)) * 12 * 1024; },
              [](Int a) { return ((Int(3) << 20) - a * a) * 6; }, Int(16) << 20};
    case L2Kind::centred:  // 1 + |u-1/2|/2 + |v-1/2|/2 - |u-v|/2; 1 + |u-1/2|/2 - |u-1/2|^2/2;
                           // 13/12
      return {[](Int a, Int c) {
                return kF + 6 * 1024 * (abs_int(a - 512) + abs_int(c - 512) - abs_int(a - c));
              },
              [](Int a) { return kF + 6 * 1024 * abs_int(a - 512) - 6 * (a - 512) * (a - 512); },
              Int(13) << 20};
    case L2Kind::wrap_around:  // 3/2 - |u-v| (1 - |u-v|); D^2 = -(4/3)^2 + pairs / N^2
      return {[](Int a, Int c) {
                return (Int(18) << 20) - 12 * abs_int(a - c) * (1024 - abs_int(a - c));
              },
              [](Int) { return Int(16) << 20; }, Int(16) << 20};
    case L2Kind::unanchored:  // min(u, v) - u v; u (1 - u) / 2; 1/12
      return {[](Int a, Int c) { return 12 * (1024 * std::min(a, c) - a * c); },
              [](Int a) { return 6 * a * (1024 - a); }, Int(1) << 20};
    case L2Kind::symmetric:  // 2 (1 - |u-v|) (the 2^s factor); 1 + 2u - 2u^2; 4/3
      return {[](Int a, Int c) { return 24 * 1024 * (1024 - abs_int(a - c)); },
              [](Int a) { return 12 * ((Int(1) << 20) + 2048 * a - 2 * a * a); }, Int(16) << 20};
    case L2Kind::mixture:  // Zhou, Fang & Ning 2013, Eq. (13) with d = 2; scipy.stats.qmc's form
      // 15/8 - |u-1/2|/4 - |v-1/2|/4 - 3|u-v|/4 + |u-v|^2/2; 5/3 - |u-1/2|/4 - |u-1/2|^2/4; 19/12
      return {[](Int a, Int c) {
                return (Int(45) << 19) - 3 * 1024 * (abs_int(a - 512) + abs_int(c - 512)) -
                       9 * 1024 * abs_int(a - c) + 6 * (a - c) * (a - c);
              },
              [](Int a) {
                return (Int(20) << 20) - 3 * 1024 * abs_int(a - 512) - 3 * (a - 512) * (a - 512);
              },
              Int(19) << 20};
  }
  return {};
}

double exact_squared(L2Kind kind, const std::vector<std::pair<int, int>>& ab) {
  const ExactForm f = exact_form(kind);
  const Int n = static_cast<Int>(ab.size());
  Int single = 0, pairs = 0;
  for (const auto& [a, b] : ab) {
    single += f.single(a) * f.single(b);
    for (const auto& [c, d] : ab) pairs += f.pair(a, c) * f.pair(b, d);
  }
  const Int t = f.constant * f.constant * n * n - 2 * n * single + pairs;
  return static_cast<double>(t) / (static_cast<double>(n * n) * static_cast<double>(kF * kF));
}

std::vector<Vec2> on_grid(const std::vector<std::pair<int, int>>& ab) {
  std::vector<Vec2> p;
  for (const auto& [a, b] : ab) p.push_back({a / 1024.0, b / 1024.0});
  return p;
}

RC_GTEST_PROP(L2Discrepancy, EveryKindAgreesWithExactArithmeticTo1e12, ()) {
  const int n = *rc::gen::inRange(1, 120);
  std::vector<std::pair<int, int>> ab;
  for (int i = 0; i < n; ++i) {
    // Often on a coarse grid, so that ties (and points on the centre lines) are common.
    const int step = *rc::gen::element(1, 64, 256);
    ab.push_back(
        {*rc::gen::inRange(0, 1025 / step) * step, *rc::gen::inRange(0, 1025 / step) * step});
  }
  const auto p = on_grid(ab);
  for (const L2KindInfo& k : l2_kinds()) {
    const double exact = exact_squared(k.kind, ab), got = l2_discrepancy(p, k.kind);
    RC_ASSERT(exact > 0);
    RC_ASSERT(std::abs(got * got - exact) <= 1e-12 * exact);
  }
}

TEST(L2Discrepancy, ThousandsOfPointsAgreeWithExactArithmetic) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> u(0, 1024);
  std::vector<std::pair<int, int>> ab(2000);
  for (auto& [a, b] : ab) a = u(rng), b = u(rng);
  const auto p = on_grid(ab);
  for (const L2KindInfo& k : l2_kinds()) {
    const double exact = exact_squared(k.kind, ab), got = l2_discrepancy(p, k.kind);
    EXPECT_NEAR(got * got, exact, 1e-12 * exact) << k.name;
  }
}

// The forms themselves, from the definition: each discrepancy is the mean
// squared local discrepancy over a family of boxes (with every projection
// where the header's a is 1). The family is a product of 1D families, so the
// square expands into per-coordinate integrals, computed here by quadrature
// over the 1D boxes: A(s, t) the measure of the boxes holding both, C(s)
// the integral of the length of those holding s, K of the squared length.
struct Family1D {
  double projections;
  // Calls f(contains, length, measure) for the boxes of a quadrature rule.
  std::function<void(
      const std::function<void(const std::function<bool(double)>&, double, double)>&)>
      boxes;
};

Family1D family(L2Kind kind) {
  constexpr int kSteps = 200000;
  auto anchored = [](const auto& f) {  // [0, t)
    for (int i = 0; i < kSteps; ++i) {
      const double t = (i + 0.5) / kSteps;
      f([t](double s) { return s < t; }, t, 1.0 / kSteps);
    }
  };
  switch (kind) {
    case L2Kind::star:
      return {0, anchored};
    case L2Kind::generalized:
      return {1, anchored};
    case L2Kind::centred:  // from t to its nearest corner
      return {1, [](const auto& f) {
                for (int i = 0; i < kSteps; ++i) {
                  const double t = (i + 0.5) / kSteps;
                  if (t < 0.5)
                    f([t](double s) { return s < t; }, t, 1.0 / kSteps);
                  else
                    f([t](double s) { return s >= t; }, 1 - t, 1.0 / kSteps);
                }
              }};
    case L2Kind::unanchored:  // [s, t), s < t
      return {0, [](const auto& f) {
                constexpr int m = 2000;
                for (int i = 0; i < m; ++i)
                  for (int j = i; j < m; ++j) {
                    const double lo = (i + 0.5) / m, hi = (j + 0.5) / m;
                    const double w = (i == j ? 0.5 : 1.0) / (double(m) * m);
                    f([lo, hi](double s) { return lo <= s && s < hi; }, hi - lo, w);
                  }
              }};
    case L2Kind::wrap_around:  // the arc from s of length l on the circle
      return {
          1, [](const auto& f) {
            constexpr int m = 2000;
            for (int i = 0; i < m; ++i)
              for (int j = 0; j < m; ++j) {
                const double start = (i + 0.5) / m, length = (j + 0.5) / m;
                f([start, length](double s) { return s - start - std::floor(s - start) < length; },
                  length, 1.0 / (double(m) * m));
              }
          }};
    case L2Kind::symmetric:
    case L2Kind::mixture:  // not the measure of a box family
      break;
  }
  return {};
}

double definition_squared(L2Kind kind, const std::vector<Vec2>& p) {
  const Family1D fam = family(kind);
  const size_t n = p.size();
  // Per coordinate: A for every pair, C for every point, K.
  auto per_coordinate = [&](auto coordinate, std::vector<double>& pair, std::vector<double>& single,
                            double& box) {
    pair.assign(n * n, 0.0);
    single.assign(n, 0.0);
    box = 0;
    std::vector<char> in(n);
    fam.boxes([&](const std::function<bool(double)>& contains, double length, double measure) {
      for (size_t i = 0; i < n; ++i) in[i] = contains(coordinate(p[i]));
      for (size_t i = 0; i < n; ++i) {
        if (!in[i]) continue;
        single[i] += length * measure;
        for (size_t j = 0; j < n; ++j)
          if (in[j]) pair[i * n + j] += measure;
      }
      box += length * length * measure;
    });
  };
  std::vector<double> ax, cx, ay, cy;
  double kx, ky;
  per_coordinate([](Vec2 v) { return v.x; }, ax, cx, kx);
  per_coordinate([](Vec2 v) { return v.y; }, ay, cy, ky);
  const double a = fam.projections, nn = static_cast<double>(n);
  double single = 0, pairs = 0;
  for (size_t i = 0; i < n; ++i) {
    single += (a + cx[i]) * (a + cy[i]);
    for (size_t j = 0; j < n; ++j) pairs += (a + ax[i * n + j]) * (a + ay[i * n + j]);
  }
  return (a + kx) * (a + ky) - 2 * single / nn + pairs / (nn * nn);
}

TEST(L2Discrepancy, TheFormsAreTheMeanSquaredLocalDiscrepancyOverTheirBoxes) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec2> p(6);
  for (auto& v : p) v = {u(rng), u(rng)};
  for (const L2Kind kind : {L2Kind::star, L2Kind::generalized, L2Kind::centred, L2Kind::wrap_around,
                            L2Kind::unanchored}) {
    const double d = l2_discrepancy(p, kind), reference = definition_squared(kind, p);
    // The midpoint rule on a discontinuous integrand: O(1 / steps), 2e-6 with
    // 200,000 steps in 1D, 1e-3 on the 2000^2 grids of the 2D families.
    const bool two_d = kind == L2Kind::wrap_around || kind == L2Kind::unanchored;
    EXPECT_NEAR(d * d, reference, (two_d ? 3e-3 : 1e-5) * reference) << l2_kind_info(kind).name;
  }
}

// The O(N^2) pair sums of each form in double-double, for arbitrary doubles
// (not on a grid) at sizes where the terms cancel to 1e-7 of themselves.
TEST(L2Discrepancy, TheSweepsAgreeWithTheCompensatedPairSums) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec2> p(1500);
  for (auto& v : p) v = {u(rng), u(rng)};
  const double n = static_cast<double>(p.size());
  // The symmetric form: (4/3)^2 - (2/N) sum prod (1 + 2u - 2u^2) + (4/N^2) sum prod (1 - |u - v|).
  DoubleDouble single, pairs;
  auto one_minus_distance = [](double s, double t) {
    return DoubleDouble(1) - (s > t ? two_sum(s, -t) : two_sum(t, -s));
  };
  auto quadratic = [](double s) { return DoubleDouble(1) + two_prod(2, s) - two_prod(2 * s, s); };
  for (const Vec2& a : p) {
    single += quadratic(a.x) * quadratic(a.y);
    for (const Vec2& b : p) pairs += one_minus_distance(a.x, b.x) * one_minus_distance(a.y, b.y);
  }
  const DoubleDouble four_thirds = DoubleDouble(4) / 3;
  const double reference =
      (four_thirds * four_thirds - single * 2.0 / n + pairs * 4.0 / n / n).value();
  const double got = l2_discrepancy(p, L2Kind::symmetric);
  EXPECT_NEAR(got * got, reference, 1e-12 * reference);
}

std::vector<std::pair<int, int>> random_grid(uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(0, 1023);
  std::vector<std::pair<int, int>> ab(n);
  for (auto& [a, b] : ab) a = u(rng), b = u(rng);
  return ab;
}

// The wrap-around discrepancy sees the torus: a translation (mod 1) keeps it.
RC_GTEST_PROP(L2Discrepancy, WrapAroundIsTranslationInvariant, ()) {
  auto ab = random_grid(*rc::gen::arbitrary<uint64_t>(), *rc::gen::inRange(1, 100));
  const double before = l2_discrepancy(on_grid(ab), L2Kind::wrap_around);
  const int dx = *rc::gen::inRange(0, 1024), dy = *rc::gen::inRange(0, 1024);
  for (auto& [a, b] : ab) a = (a + dx) % 1024, b = (b + dy) % 1024;
  RC_ASSERT(std::abs(l2_discrepancy(on_grid(ab), L2Kind::wrap_around) - before) <= 1e-12 * before);
}

// The centred, symmetric and mixture discrepancies treat every corner alike:
// a reflection of either axis, or swapping them, keeps them.
RC_GTEST_PROP(L2Discrepancy, CentredSymmetricAndMixtureAreReflectionInvariant, ()) {
  auto ab = random_grid(*rc::gen::arbitrary<uint64_t>(), *rc::gen::inRange(1, 100));
  auto reflected = ab;
  for (auto& [a, b] : reflected) a = 1024 - a, std::swap(a, b);
  for (const L2Kind kind : {L2Kind::centred, L2Kind::symmetric, L2Kind::mixture}) {
    const double before = l2_discrepancy(on_grid(ab), kind);
    RC_ASSERT(std::abs(l2_discrepancy(on_grid(reflected), kind) - before) <= 1e-12 * before);
  }
}

TEST(L2Discrepancy, ClosedFormsOfOnePoint) {
  // The centre: centred D^2 = (13/12)^2 - 2 + 1; unanchored (1/12)^2 - 2 (1/8)^2 + (1/4)^2.
  EXPECT_NEAR(l2_discrepancy({{0.5, 0.5}}, L2Kind::centred), std::sqrt(169.0 / 144 - 1), 1e-15);
  EXPECT_NEAR(l2_discrepancy({{0.5, 0.5}}, L2Kind::unanchored),
              std::sqrt(1.0 / 144 - 2.0 / 64 + 1.0 / 16), 1e-15);
  // One point anywhere on the torus: -(4/3)^2 + (3/2)^2.
  EXPECT_NEAR(l2_discrepancy({{0.3, 0.8}}, L2Kind::wrap_around), std::sqrt(2.25 - 16.0 / 9), 1e-15);
  // The mixture discrepancy of the centre: (19/12)^2 - 2 (5/3)^2 + (15/8)^2.
  EXPECT_NEAR(l2_discrepancy({{0.5, 0.5}}, L2Kind::mixture),
              std::sqrt(361.0 / 144 - 50.0 / 9 + 225.0 / 64), 1e-15);
  // No points: the boxes' areas alone (the star's 1/3, as before).
  EXPECT_NEAR(l2_discrepancy({}, L2Kind::star), 1.0 / 3, 1e-15);
  EXPECT_EQ(l2_star_discrepancy({{0.25, 0.75}}), l2_discrepancy({{0.25, 0.75}}, L2Kind::star));
}

}  // namespace
}  // namespace aapat
