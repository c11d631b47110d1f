// A weights-only run's held positions (held_positions.h) and the minimax
// direction's Frank-Wolfe (min_norm_point.h) give the general path's bits on
// every SIMD path, so that an optimizer run takes the same steps with them.
#include "aapat/optimize/held_positions.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/min_norm_point.h"
#include "aapat/optimize/problem_e2.h"
#include "testing/every_simd_path.h"

namespace aapat {
namespace {

struct Evaluation {
  double e2 = 0;
  std::vector<double> values;
  Direction heuristic, minimax;
};

// E2, its per-term values and both weight directions, from the general path
// or from positions held first.
Evaluation evaluate(const ProblemE2& objective, const Problem& problem, bool hold) {
  Workspace ws;
  objective.e2(problem, ws);
  if (hold) ws.held.hold(objective.metric(), ws.kernels);
  Evaluation r;
  r.e2 = objective.e2(problem, ws);
  r.values = ws.values;
  objective.heuristic_direction(problem, ws, r.e2, 0.99, 100, false, r.heuristic);
  objective.minimax_direction(problem, ws, r.e2, 0.9, false, r.minimax);
  return r;
}

RC_GTEST_PROP(HeldPositions, GiveTheGeneralPathsBitsOnEveryPath, ()) {
  const char* families[] = {"P(1,1,4)", "P(1,1+,2)", "P(4,1+,2)", "P(4,4,3)", "P(1,1,6)"};
  const size_t f = *rc::gen::inRange<size_t>(0, std::size(families));
  const char* filters[] = {"mitchell", "gaussian", "box", "lanczos:lobes=2"};
  const Filter filter = make_filter(filters[*rc::gen::inRange<size_t>(0, std::size(filters))]);
  const double norms[] = {Metric::kMaxNorm, 1, 2, 8};
  const AcuityTable acuity =
      *rc::gen::arbitrary<bool>() ? laine_aila_acuity() : uniform_acuity(*rc::gen::inRange(1, 30));
  const Metric metric(filter, acuity, norms[*rc::gen::inRange(0, 4)]);
  auto rng = start_rng(*rc::gen::arbitrary<uint64_t>(), 0);
  Problem problem = problem_from_pattern(
      seed_pattern(parse_family(families[f], ""), SeedKind::kJittered, rng, filter));
  std::uniform_real_distribution<double> weight(-0.2, 1);
  for (double& w : problem.weights) w = weight(rng);
  project_to_constraints(problem, false);
  const ProblemE2 objective(metric);
  testing::EveryPath paths;
  paths.run([&] {
    const Evaluation general = evaluate(objective, problem, false);
    const Evaluation held = evaluate(objective, problem, true);
    RC_ASSERT(held.e2 == general.e2);
    RC_ASSERT(held.values == general.values);
    RC_ASSERT(held.heuristic.w == general.heuristic.w);
    RC_ASSERT(held.minimax.w == general.minimax.w);
  });
}

TEST(HeldPositions, HoldNothingPastThePairForm) {
  // 25 samples sort instead of summing pairs: not held, the general path runs.
  std::vector<Vec2> positions;
  for (int i = 0; i < 25; ++i) positions.push_back({0.04 * i - 0.5, 0.5 - 0.03 * i});
  const Kernel big = make_kernel(positions, std::vector<double>(25, 1.0 / 25));
  const Metric metric(make_filter("mitchell"), laine_aila_acuity());
  HeldPositions held;
  held.hold(metric, std::span<const Kernel>(&big, 1));
  EXPECT_FALSE(held.held());
  const Kernel small = make_kernel({{0.1, 0.2}, {-0.3, 0.1}}, {0.5, 0.5});
  held.hold(metric, std::span<const Kernel>(&small, 1));
  EXPECT_TRUE(held.held());
  EXPECT_TRUE(held.holds(0, small));
  EXPECT_FALSE(held.holds(0, make_kernel({{0.1, 0.2}, {-0.3, 0.2}}, {0.5, 0.5})));
}

// The scalar Frank-Wolfe the minimax direction ran before min_norm_combination.
std::vector<double> scalar_min_norm(const std::vector<double>& gram, size_t m) {
  std::vector<double> lambda(m, 1.0 / m), q(m);
  for (int it = 0; it < 200 && m > 1; ++it) {
    std::fill(q.begin(), q.end(), 0.0);
    for (size_t j = 0; j < m; ++j)
      for (size_t i = 0; i < m; ++i) q[i] += gram[j * m + i] * lambda[j];
    const size_t best = std::min_element(q.begin(), q.end()) - q.begin();
    double lq = 0;
    for (size_t i = 0; i < m; ++i) lq += lambda[i] * q[i];
    const double num = lq - q[best], den = lq - 2 * q[best] + gram[best * m + best];
    if (num <= 1e-18 * std::max(1.0, lq) || den <= 0) break;
    const double gamma = std::min(1.0, num / den);
    for (double& l : lambda) l *= 1 - gamma;
    lambda[best] += gamma;
  }
  return lambda;
}

TEST(MinNormPoint, TheScalarLoopsBitsOnEveryPath) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  for (const size_t m : {1, 2, 7, 33, 80}) {
    // The Gram matrix of m random vectors in 6 dimensions.
    std::vector<double> v(m * 6), gram(m * m);
    for (double& x : v) x = normal(rng);
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j)
        for (size_t c = 0; c < 6; ++c) gram[i * m + j] += v[i * 6 + c] * v[j * 6 + c];
    const std::vector<double> expected = scalar_min_norm(gram, m);
    testing::EveryPath paths;
    paths.run([&] { EXPECT_EQ(min_norm_combination(gram, m), expected) << m; });
  }
}

TEST(MinNormPoint, FromTheVectorsTheSameWalkAndTheSameBitsOnEveryPath) {
  std::mt19937_64 rng(6);
  std::normal_distribution<double> normal;
  for (const size_t m : {1, 2, 7, 33, 80}) {
    // m random vectors in 6 dimensions, shifted off the origin so that the
    // nearest point lies on a face of the hull, as a minimax direction's does.
    const size_t dim = 6;
    std::vector<double> columns(dim * m), gram(m * m);
    for (size_t c = 0; c < dim; ++c)
      for (size_t i = 0; i < m; ++i) columns[c * m + i] = normal(rng) + (c == 0 ? 1.5 : 0.0);
    for (size_t i = 0; i < m; ++i)
      for (size_t j = 0; j < m; ++j)
        for (size_t c = 0; c < dim; ++c) gram[i * m + j] += columns[c * m + i] * columns[c * m + j];
    const std::vector<double> by_gram = min_norm_combination(gram, m);
    std::vector<double> first;
    testing::EveryPath paths;
    paths.run([&] {
      const std::vector<double> lambda = min_norm_combination_of_vectors(columns, m, dim);
      if (first.empty()) first = lambda;
      EXPECT_EQ(lambda, first) << m;
    });
    // The same point as the Gram form's: each step is the same up to rounding.
    for (size_t c = 0; c < dim; ++c) {
      double a = 0, b = 0;
      for (size_t i = 0; i < m; ++i) {
        a += first[i] * columns[c * m + i];
        b += by_gram[i] * columns[c * m + i];
      }
      EXPECT_NEAR(a, b, 1e-12) << m << " " << c;
    }
  }
}

TEST(MinNormPoint, FindsTheNearestPointOfTheHull) {
  // (1, 0) and (0, 1): the segment between them is nearest the origin at its middle.
  const std::vector<double> lambda = min_norm_combination(std::vector<double>{1, 0, 0, 1}, 2);
  EXPECT_NEAR(lambda[0], 0.5, 1e-12);
  EXPECT_NEAR(lambda[1], 0.5, 1e-12);
  // (2, 0) and (1, 1): the hull's nearest point is (1, 1) itself.
  const std::vector<double> corner = min_norm_combination(std::vector<double>{4, 2, 2, 2}, 2);
  EXPECT_NEAR(corner[1], 1.0, 1e-9);
  // The same two hulls from their vectors (columns: every vector's x, then y).
  const std::vector<double> middle =
      min_norm_combination_of_vectors(std::vector<double>{1, 0, 0, 1}, 2, 2);
  EXPECT_NEAR(middle[0], 0.5, 1e-12);
  EXPECT_NEAR(middle[1], 0.5, 1e-12);
  const std::vector<double> vertex =
      min_norm_combination_of_vectors(std::vector<double>{2, 1, 0, 1}, 2, 2);
  EXPECT_NEAR(vertex[1], 1.0, 1e-9);
}

}  // namespace
}  // namespace aapat
