#include "aapat/temporal/sequence/sequence_generators.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "aapat/generate/catalog.h"
#include "aapat/generate/point_generators.h"

namespace aapat {
namespace {

Vec2 offset(const Sequence& s, int f) {
  return s.frames[static_cast<size_t>(f)].sets[0][0];
}

// FSR 2's jitter: Halton(2, 3) from index 1, minus 1/2.
TEST(SequenceGenerators, HaltonStartsAtIndexOneLikeTheUpscalers) {
  const Sequence s = make_sequence("halton:frames=4");
  EXPECT_EQ(offset(s, 0).x, 0.0);  // h2(1) = 1/2
  EXPECT_DOUBLE_EQ(offset(s, 0).y, 1.0 / 3 - 0.5);
  EXPECT_DOUBLE_EQ(offset(s, 1).x, 0.25 - 0.5);  // h2(2) = 1/4
  EXPECT_DOUBLE_EQ(offset(s, 1).y, 2.0 / 3 - 0.5);
  EXPECT_DOUBLE_EQ(offset(s, 2).x, 0.75 - 0.5);
  EXPECT_DOUBLE_EQ(offset(s, 2).y, 1.0 / 9 - 0.5);
  const Sequence zero = make_sequence("halton:frames=2,start=0");
  EXPECT_EQ(offset(zero, 0).x, -0.5);  // index 0: the pixel's corner
  EXPECT_DOUBLE_EQ(radical_inverse_of(11, 3), 2.0 / 3 + 0.0 / 9 + 1.0 / 27);  // 11 = 102 in base 3
}

// The resonances of docs/temporal.md ("What a jitter can deliver under
// motion"): seen from a display pixel, frame n's sample sits at
// delta_n = j_n - n v (mod 1) for a pan of v pixels per frame, so two frames
// coincide where j_n - j_m = (n - m) v (mod 1). Halton base 2 pairs its
// indices 2i, 2i+1 at 1/2 apart (phi(2i+1) = phi(2i) + 1/2): at 1/2 px per
// frame in x each pair lands on one place; base 3 does it with triples at
// 1/3 in y; R2 steps by its own alpha, so at v = alpha every frame lands on
// one place in both axes.
TEST(SequenceGenerators, ResonantVelocitiesCollapseTheSequences) {
  const auto seen = [](const Sequence& s, int n, Vec2 v) {
    const Vec2 j = offset(s, n);
    const auto wrap = [](double t) { return t - std::floor(t); };
    return Vec2{wrap(j.x - n * v.x), wrap(j.y - n * v.y)};
  };
  const auto same = [](double a, double b) {  // on the circle
    const double d = std::abs(a - b);
    return std::min(d, 1 - d) < 1e-12;
  };
  const Sequence halton = make_sequence("halton:frames=18");  // indices 1..18
  for (int n = 1; n + 1 < 18; n += 2) {                       // frames 1, 2 hold indices 2, 3
    EXPECT_TRUE(same(seen(halton, n, {0.5, 0}).x, seen(halton, n + 1, {0.5, 0}).x)) << n;
    EXPECT_FALSE(same(seen(halton, n, {0.3, 0}).x, seen(halton, n + 1, {0.3, 0}).x)) << n;
  }
  for (int n = 2; n + 2 < 18; n += 3)  // frames 2, 3, 4 hold indices 3, 4, 5
    for (int k = 1; k <= 2; ++k)
      EXPECT_TRUE(same(seen(halton, n, {0, 1.0 / 3}).y, seen(halton, n + k, {0, 1.0 / 3}).y));
  const Sequence r2 = make_sequence("r2:frames=16");
  const double g = kPlasticNumber;
  const Vec2 alpha{1 / g, 1 / (g * g)};
  for (int n = 1; n < 16; ++n) {
    EXPECT_NEAR(std::remainder(seen(r2, n, alpha).x - seen(r2, 0, alpha).x, 1.0), 0, 1e-9) << n;
    EXPECT_NEAR(std::remainder(seen(r2, n, alpha).y - seen(r2, 0, alpha).y, 1.0), 0, 1e-9) << n;
  }
}

TEST(SequenceGenerators, R2IsThePlasticNumbersLattice) {
  const double g = kPlasticNumber;
  EXPECT_NEAR(g * g * g, g + 1, 1e-15);
  const Sequence s = make_sequence("r2:frames=3");
  EXPECT_NEAR(offset(s, 0).x, std::fmod(0.5 + 1 / g, 1.0) - 0.5, 1e-15);
  EXPECT_NEAR(offset(s, 2).y, std::fmod(0.5 + 3 / (g * g), 1.0) - 0.5, 1e-15);
}

// Unscrambled Sobol: (0, 0), (1/2, 1/2), (1/4, 3/4), (3/4, 1/4), ...; Owen
// scrambling keeps every power-of-two prefix a (0, m, 2)-net, so 16 points
// are N-rooks in both axes, for any seed.
TEST(SequenceGenerators, SobolIsANetScrambledOrNot) {
  const Sequence plain = make_sequence("sobol:frames=4,seed=0");
  const std::vector<Vec2> expected{{0, 0}, {0.5, 0.5}, {0.25, 0.75}, {0.75, 0.25}};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(offset(plain, i).x + 0.5, expected[static_cast<size_t>(i)].x);
    EXPECT_EQ(offset(plain, i).y + 0.5, expected[static_cast<size_t>(i)].y);
  }
  for (int seed : {1, 2, 77}) {
    const Sequence s = make_sequence(fmt::format("sobol:frames=16,seed={}", seed));
    std::set<int> xs, ys;
    for (int i = 0; i < 16; ++i) {
      xs.insert(static_cast<int>(std::floor((offset(s, i).x + 0.5) * 16)));
      ys.insert(static_cast<int>(std::floor((offset(s, i).y + 0.5) * 16)));
    }
    EXPECT_EQ(xs.size(), 16u) << seed;
    EXPECT_EQ(ys.size(), 16u) << seed;
  }
}

// White noise is the point generator's uniform points less 1/2, so the two
// faces of "random" with one seed are the same points.
TEST(SequenceGenerators, RandomIsThePointGeneratorsUniformPoints) {
  for (uint64_t seed : {0, 1, 9}) {
    const Sequence s = make_sequence(fmt::format("random:frames=18,seed={}", seed));
    const std::vector<Vec2> points = generate_points("random", 18, seed);
    ASSERT_EQ(s.period(), 18);
    for (int f = 0; f < 18; ++f) {
      EXPECT_EQ(offset(s, f).x, points[size_t(f)].x - 0.5) << seed << " " << f;
      EXPECT_EQ(offset(s, f).y, points[size_t(f)].y - 0.5) << seed << " " << f;
    }
  }
  EXPECT_NE(offset(make_sequence("random:seed=1"), 0).x,
            offset(make_sequence("random:seed=2"), 0).x);
}

// At R = 3/2 display centres fall at render offsets -1/3, 0, 1/3: nine
// frames visit each pair once and every three consecutive frames each offset
// once per axis; at R = 2, -1/4 and 1/4 in four frames.
TEST(SequenceGenerators, DisplayLatticeVisitsEveryDisplayPhaseInALatinOrder) {
  const Sequence s = make_sequence("display-lattice:ratio=1.5");
  ASSERT_EQ(s.period(), 9);
  std::set<std::pair<int, int>> pairs;
  for (int k = 0; k < 9; ++k) {
    const int i = static_cast<int>(std::lround(3 * offset(s, k).x)),
              j = static_cast<int>(std::lround(3 * offset(s, k).y));
    EXPECT_NEAR(offset(s, k).x, i / 3.0, 1e-12);
    EXPECT_NEAR(offset(s, k).y, j / 3.0, 1e-12);
    pairs.insert({i, j});
  }
  EXPECT_EQ(pairs.size(), 9u);
  for (int first : {0, 3, 6}) {
    std::set<int> xs, ys;
    for (int k = first; k < first + 3; ++k) {
      xs.insert(static_cast<int>(std::lround(3 * offset(s, k).x)));
      ys.insert(static_cast<int>(std::lround(3 * offset(s, k).y)));
    }
    EXPECT_EQ(xs.size(), 3u);
    EXPECT_EQ(ys.size(), 3u);
  }
  const Sequence two = make_sequence("display-lattice:ratio=2,frames=6");
  ASSERT_EQ(two.period(), 6);
  EXPECT_NEAR(offset(two, 0).x, -0.25, 1e-12);
  EXPECT_NEAR(offset(two, 1).x, 0.25, 1e-12);
  EXPECT_NEAR(offset(two, 4).x, -0.25, 1e-12);  // the cycle of four again
  EXPECT_NEAR(offset(two, 4).y, -0.25, 1e-12);
  EXPECT_THROW(make_sequence("display-lattice:ratio=0.5"), Error);
}

}  // namespace
}  // namespace aapat
