// The optimizer against Laine-Aila Table 2 "Best E2" and Hasselgren Table 2,
// its gradients through the parameterization, its constraints and determinism.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "aapat/core/filter_catalog.h"
#include "aapat/generate/catalog.h"
#include "aapat/optimize/descent.h"
#include "aapat/optimize/family.h"
#include "aapat/optimize/multistart.h"
#include "aapat/optimize/problem_e2.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

const Metric& default_metric() {
  static const Metric m(make_filter("mitchell"), laine_aila_acuity());
  return m;
}

MultiStartResult search(const std::string& family, const std::string& placement, int starts,
                        uint64_t seed = 1, int threads = 0,
                        const Metric& metric = default_metric()) {
  const FamilySpec spec = parse_family(family, placement);
  return multistart(metric, starts, seed,
                    family_seeds(spec, SeedKind::kJittered, seed, metric.filter()),
                    OptimizerSettings{}, threads);
}

double best_e2(const MultiStartResult& r) {
  return r.starts[r.best].run.final_e2;
}

// Laine-Aila Table 2, "Best E2" column, reached from random starts. The paper
// prints three decimals: "<= 0.359" is read as rounding to 0.359 (< 0.3595).
TEST(LaineAilaTable2, BestE2FromRandomStarts) {
  EXPECT_LT(best_e2(search("P(1,1,4)", "", 32)), 0.3595);
  EXPECT_LT(best_e2(search("P(4,1+,2)", "left,right,bottom,top", 32)), 0.3595);    // FLIPQUAD sites
  EXPECT_LE(best_e2(search("P(4,1+,1.25)", "top-left,bottom,right", 32)), 0.560);  // FLIPTRI sites
  // Quincunx sites: the weight-optimized Quincunx of Hasselgren Table 2 is 0.484.
  EXPECT_LE(best_e2(search("P(1,1+,2)", "inside,bottom-left,bottom-right,top-left,top-right", 32)),
            0.485);
}

// Laine-Aila Table 2 lists 0.359 as the best P(1,1+,2), but the Quincunx
// kernel projects on the y axis (horizontal edges) at three places only:
// -1/2, the centre's y and +1/2. E1^2 is quadratic in the weights, so the
// best weights for each centre y solve a small linear system; scanning y
// bounds W(0) E1(0), and so E2, from below. The bound is 0.4842 (centre at
// y = 0, corners 0.1475 each: Hasselgren's weight-optimized Quincunx), not
// the 0.466 the issue estimates; a brute-force grid over y and the weights
// with an independent numerical integrator gives the same 0.48421.
TEST(LaineAilaTable2, QuincunxPlacementIsBoundedAtHorizontalEdges) {
  const Filter& f = default_metric().filter();
  double bound = INFINITY;
  for (int i = 0; i <= 1000; ++i) {
    const double y = -0.5 + i / 1000.0;
    const double p[3] = {-0.5, y, 0.5};
    // Minimize sum w J - (1/2) sum w w |p - p| subject to sum w = 1:
    // J_j - sum_k |p_j - p_k| w_k = lambda for every j.
    double a[4][5] = {};
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) a[j][k] = std::abs(p[j] - p[k]);
      a[j][3] = 1;
      a[j][4] = f.abs_moment(p[j]);
    }
    a[3][0] = a[3][1] = a[3][2] = 1;
    a[3][4] = 1;
    for (int c = 0; c < 4; ++c) {  // Gauss-Jordan with partial pivoting
      int piv = c;
      for (int r = c + 1; r < 4; ++r)
        if (std::abs(a[r][c]) > std::abs(a[piv][c])) piv = r;
      std::swap(a[c], a[piv]);
      if (std::abs(a[c][c]) < 1e-14) break;
      for (int r = 0; r < 4; ++r) {
        if (r == c) continue;
        const double m = a[r][c] / a[c][c];
        for (int k = c; k < 5; ++k) a[r][k] -= m * a[c][k];
      }
    }
    std::vector<double> w = {a[0][4] / a[0][0], a[1][4] / a[1][1], a[2][4] / a[2][2]};
    if (!std::isfinite(w[0] + w[1] + w[2])) continue;
    bound = std::min(bound, 3.93 * std::sqrt(e1_squared(f, std::vector<double>(p, p + 3), w)));
  }
  EXPECT_NEAR(bound, 0.48421, 0.00005);
  // The optimizer, given the horizontal edge alone, finds the same bound.
  const Metric only_horizontal(make_filter("mitchell"), parse_acuity_csv("0,3.93\n", "h"));
  const double found =
      best_e2(search("P(1,1+,2)", "inside,bottom-left,bottom-right,top-left,top-right", 16, 1, 0,
                     only_horizontal));
  EXPECT_GE(found, bound - 1e-6);
  EXPECT_LT(found, bound + 0.002);
}

// Hasselgren Table 2: schemes A-F re-optimized from their Appendix A values.
TEST(HasselgrenTable2, SchemesReoptimizedEndAtOrBelowPublishedE2) {
  const std::vector<std::pair<std::string, double>> published = {
      {"hasselgren-a", 0.554}, {"hasselgren-b", 0.531}, {"hasselgren-c", 0.527},
      {"hasselgren-d", 0.497}, {"hasselgren-e", 0.488}, {"hasselgren-f", 0.359}};
  const ProblemE2 objective(default_metric());
  for (const auto& [name, e2] : published) {
    const Pattern start = catalog_pattern(name);
    Problem problem = problem_from_pattern(start);
    OptimizerSettings polish;
    polish.method = Method::kMinimax;
    const RunResult r = descend(objective, problem, polish);
    EXPECT_LT(r.final_e2, e2 + 0.0005) << name;  // at or below, to the paper's rounding
    EXPECT_LE(r.final_e2, r.initial_e2) << name;
    const Pattern end = pattern_of(problem);
    EXPECT_NO_THROW(validate(end));
    EXPECT_EQ(family(end), family(start)) << name;  // n kept: border samples stayed on borders
    EXPECT_TRUE(is_mirrored_tile(end)) << name;
  }
}

TEST(Optimizer, SameSeedSameResultAnyThreadCount) {
  const auto one = search("P(4,1+,1.5)", "left,bottom,top", 12, 5, 1);
  const auto two = search("P(4,1+,1.5)", "left,bottom,top", 12, 5, 2);
  EXPECT_EQ(one.starts[one.best].start, two.starts[two.best].start);
  const Pattern a = pattern_of(one.best_problem), b = pattern_of(two.best_problem);
  EXPECT_EQ(a.weights, b.weights);
  ASSERT_EQ(a.sets.size(), b.sets.size());
  for (size_t k = 0; k < a.sets.size(); ++k)
    for (size_t i = 0; i < a.sets[k].size(); ++i) {
      EXPECT_EQ(a.sets[k][i].x, b.sets[k][i].x);
      EXPECT_EQ(a.sets[k][i].y, b.sets[k][i].y);
    }
  for (size_t i = 0; i < one.starts.size(); ++i)
    EXPECT_EQ(one.starts[i].run.final_e2, two.starts[i].run.final_e2);
}

TEST(Optimizer, WeightsOnlyKeepsPositionsAndNonNegativeKeepsSigns) {
  const ProblemE2 objective(default_metric());
  Problem problem = problem_from_pattern(catalog_pattern("quincunx"));
  OptimizerSettings s;
  s.weights_only = true;
  const RunResult r = descend(objective, problem, s);
  const Pattern p = pattern_of(problem);
  EXPECT_EQ(p.sets, catalog_pattern("quincunx").sets);
  EXPECT_LT(r.final_e2, 0.4845);  // Hasselgren's weight-optimized Quincunx: 0.484
  EXPECT_NEAR(p.weights[0][0], 0.41, 0.01);

  Problem q = problem_from_pattern(catalog_pattern("grid-3x3"));
  s.weights_only = false;
  s.nonnegative_weights = true;
  descend(objective, q, s);
  for (double w : q.weights) EXPECT_GE(w, 0.0);
}

// The gradient of each (kernel, angle) term through the parameterization:
// mirrored tiles, shared corners, a 2x2 footprint reading repeated sets.
TEST(Optimizer, TermGradientsMatchCentralDifferences) {
  Pattern p14 = single_pixel_pattern("p14", {{0.11, -0.23}, {-0.31, 0.27}}, {}, {2, false});
  p14.weights = {{0.1, 0.2, 0.05, 0.15, 0.1, 0.2, 0.1, 0.1}};
  const std::vector<Pattern> patterns = {catalog_pattern("hasselgren-d"),
                                         catalog_pattern("quincunx-hasselgren"), p14};
  const Metric metric(make_filter("mitchell"), uniform_acuity(30));
  const ProblemE2 objective(metric);
  for (const Pattern& pattern : patterns) {
    Problem pr = problem_from_pattern(pattern);
    Workspace ws;
    objective.e2(pr, ws);
    auto term = [&](const Problem& q, int k, int a) {
      Workspace w2;
      objective.e2(q, w2);
      return std::sqrt(w2.values[k * metric.angle_count() + a]);
    };
    for (int k = 0; k < static_cast<int>(pr.kernels.size()); ++k) {
      for (int a = 0; a < metric.angle_count(); ++a) {
        Direction d;
        objective.term_gradient(pr, ws, k, a, d);
        const double h = 1e-6;
        for (size_t g = 0; g < pr.generators.size(); ++g) {
          for (int axis = 0; axis < 2; ++axis) {
            Problem plus = pr, minus = pr;
            (axis ? plus.generators[g].pos.y : plus.generators[g].pos.x) += h;
            (axis ? minus.generators[g].pos.y : minus.generators[g].pos.x) -= h;
            const double fd = (term(plus, k, a) - term(minus, k, a)) / (2 * h);
            EXPECT_NEAR(axis ? d.pos[g].y : d.pos[g].x, fd, 1e-6)
                << pattern.name << " kernel " << k << " angle " << a << " generator " << g;
          }
        }
        for (const auto& group : pr.weight_groups) {
          for (size_t i = 1; i < group.size(); ++i) {
            Problem plus = pr, minus = pr;
            plus.weights[group[i]] += h, plus.weights[group[0]] -= h;
            minus.weights[group[i]] -= h, minus.weights[group[0]] += h;
            const double fd = (term(plus, k, a) - term(minus, k, a)) / (2 * h);
            EXPECT_NEAR(d.w[group[i]] - d.w[group[0]], fd, 1e-6) << pattern.name;
          }
        }
      }
    }
  }
}

void expect_family_error(const std::string& family, const std::string& placement,
                         const std::string& message) {
  EXPECT_EQ(testing::error_message([&] { parse_family(family, placement); }), message)
      << family << " " << placement;
}

TEST(Family, ParsesAndExplainsWhatDoesNotFit) {
  const FamilySpec fq = parse_family("P(4,1+,2)", "left,right,bottom,top");
  EXPECT_TRUE(fq.mirrored);
  EXPECT_EQ(fq.sites.size(), 4u);
  EXPECT_EQ(parse_family("P(16,16,4)", "").sites.size(), 4u);
  expect_family_error("P(4,1+,2)", "left,right,bottom",
                      "family P(4,1+,2) says n = 2 but the placement costs 1.5 (left 0.5 + right "
                      "0.5 + bottom 0.5)");
  expect_family_error("P(4,1+,1.25)", "",
                      "family P(4,1+,1.25): n = 1.25 is not a whole number of inside samples; "
                      "give a placement with border sites (corner 1/4, edge 1/2)");
  expect_family_error("P(3,1,2)", "",
                      "family P(3,1,2): s = 3 must be a square number of sets 1, 4, 9, ... 64 (a "
                      "square tile)");
  expect_family_error("Q(1,1,2)", "",
                      "family: 'Q(1,1,2)' is not of the form P(s,r,n), e.g. P(4,1+,2)");
  expect_family_error(
      "P(1,1+,1.5)", "inside,left",
      "placement: in P(1,1+,1.5) every pixel repeats the same set, so a left-edge "
      "sample is also the right-edge sample of the pixel to the left: list left and "
      "right (and top and bottom) in pairs");
  expect_family_error("P(1,1,1.5)", "inside,left",
                      "family P(1,1,1.5): border sites are shared with the neighbours, which only "
                      "a sharing footprint (r with +) reads");
  expect_family_error("P(4,1+,2)", "left,right,middle",
                      "placement: unknown site 'middle' (sites are inside, left, right, bottom, "
                      "top, bottom-left, bottom-right, top-left, top-right)");
  expect_family_error("P(4,1+,0.5)", "top-left,top-left",
                      "placement: the top-left corner holds one sample at most");
}

TEST(Family, SeedPatternsAreValidAndCostN) {
  const Filter f = make_filter("mitchell");
  for (const auto& [name, placement] : std::vector<std::pair<std::string, std::string>>{
           {"P(4,1+,2)", "left,right,bottom,top"},
           {"P(1,1+,2)", "inside,bottom-left,bottom-right,top-left,top-right"},
           {"P(1,1+,2)", "left,right,top,bottom"},
           {"P(1,4,3)", ""},
           {"P(4,4,2)", ""},
           {"P(16,16,4)", ""}}) {
    const FamilySpec spec = parse_family(name, placement);
    for (SeedKind kind : {SeedKind::kJittered, SeedKind::kPoisson, SeedKind::kUniform}) {
      auto rng = start_rng(3, 0);
      const Pattern p = seed_pattern(spec, kind, rng, f);
      EXPECT_NO_THROW(validate(p)) << name << " " << placement;
      EXPECT_EQ(family(p), name) << placement;
    }
  }
}

// One E2 evaluation: the optimizer's objective of a problem and the metric's
// E2 of the same pattern agree, for random patterns of every kind of family,
// filters and norms. Both run Metric::kernel_terms and combine_over_kernels;
// they differ only in how a kernel's inputs are assembled (the problem shifts
// generators by whole pixels, the pattern its samples, and the metric divides
// the weights by their sum), so they agree to rounding: 1e-12 relative.
RC_GTEST_PROP(ProblemE2, E2EqualsTheMetricsE2OfTheSamePattern, ()) {
  const char* families[] = {"P(1,1,4)", "P(1,1+,2)", "P(4,1+,2)",
                            "P(4,4,3)", "P(1,4,5)",  "P(9,1,2)"};
  const char* placements[] = {
      "", "inside,bottom-left,bottom-right,top-left,top-right", "left,right,bottom,top", "", "",
      ""};
  const size_t f = *rc::gen::inRange<size_t>(0, std::size(families));
  const char* filters[] = {"mitchell", "gaussian", "box", "lanczos:lobes=2"};
  const Filter filter = make_filter(filters[*rc::gen::inRange<size_t>(0, std::size(filters))]);
  const double norms[] = {Metric::kMaxNorm, 1, 2, 8};
  const Metric metric(filter, laine_aila_acuity(), norms[*rc::gen::inRange(0, 4)]);
  auto rng = start_rng(*rc::gen::arbitrary<uint64_t>(), 0);
  const FamilySpec spec = parse_family(families[f], placements[f]);
  const SeedKind kinds[] = {SeedKind::kJittered, SeedKind::kPoisson, SeedKind::kUniform};
  const Pattern p = seed_pattern(spec, kinds[*rc::gen::inRange(0, 3)], rng, filter);
  const Problem problem = problem_from_pattern(p);
  Workspace ws;
  const double objective = ProblemE2(metric).e2(problem, ws);
  RC_ASSERT(std::abs(objective - metric.evaluate(pattern_of(problem)).e2) <= 1e-12 * objective);
  RC_ASSERT(std::abs(objective - metric.evaluate(p).e2) <= 1e-12 * objective);
}

}  // namespace
}  // namespace aapat
