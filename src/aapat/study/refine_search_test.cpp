#include "aapat/study/refine_search.h"

#include <gtest/gtest.h>

#include <map>

#include "aapat/core/lattice.h"
#include "aapat/core/objective.h"
#include "aapat/generate/catalog.h"
#include "aapat/io/pattern_json.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// The start refined under a small objective (two directions, 16-pixel
// charts) for at most `tries` evaluations.
RefineResult refined(const Pattern& start, int tries) {
  const PerceptualObjective o(parse_perceptual("perceptual:angles=2,patch=16,reference=16"));
  RefineSettings s;
  s.max_tries = tries;
  return refine_pattern(start, refine_objective(o), s);
}

// The search never returns a pattern worse than its start, keeps a
// one-pixel pattern's samples strictly inside and its weights a
// non-negative partition of 1, and records the objective it refined under.
TEST(RefineSearch, NeverWorseAndOnTheConstraints) {
  const PerceptualObjective o(parse_perceptual("perceptual:angles=2,patch=16,reference=16"));
  const Pattern start = catalog_pattern("msaa-4");
  const RefineResult r = refined(start, 40);
  EXPECT_EQ(r.start_value, o(start));
  EXPECT_LE(r.value, r.start_value);
  EXPECT_EQ(o(r.pattern), r.value);
  EXPECT_LE(r.tries, 40);
  double sum = 0;
  for (double w : r.pattern.weights[0]) {
    EXPECT_GE(w, 0);
    sum += w;
  }
  EXPECT_NEAR(sum, 1, 1e-12);
  for (const Vec2& p : r.pattern.sets[0]) {
    EXPECT_LT(std::abs(p.x), 0.5);
    EXPECT_LT(std::abs(p.y), 0.5);
  }
  const auto& why = r.pattern.provenance;
  EXPECT_EQ(why[why.size() - 2].first, "refined");
  EXPECT_EQ(why.back().first, "perceptual");
  EXPECT_NEAR(std::stod(why.back().second), r.value, 1e-6);
  EXPECT_EQ(r.pattern.name, "msaa-4-perceptual");
}

// A catalog pattern's recorded E2 (what `aapat list` shows) is re-measured
// under the objective it was designed for once refined.
TEST(RefineSearch, TheRecordedE2IsTheRefinedPatterns) {
  const Pattern start = resolve_pattern("aapat-4");
  const RefineResult r = refined(start, 30);
  ASSERT_LT(r.value, r.start_value);
  std::string e2;
  for (const auto& [key, value] : r.pattern.provenance)
    if (key == "e2") e2 = value;
  const double expected = design_objective(start)->metric().evaluate(r.pattern).e2;
  EXPECT_NEAR(std::stod(e2), expected, 1e-6);
  // A published start (no design objective) records where it came from and
  // its E2 under the default objective, which then reads as its design.
  const RefineResult q = refined(catalog_pattern("hasselgren-b"), 20);
  std::map<std::string, std::string> why(q.pattern.provenance.begin(), q.pattern.provenance.end());
  EXPECT_EQ(why["refined_from"], "hasselgren-b");
  EXPECT_EQ(why["objective"], "recommended");
  EXPECT_NEAR(std::stod(why["e2"]),
              named_objective(kDefaultObjective).metric().evaluate(q.pattern).e2, 1e-6);
  EXPECT_EQ(design_objective(q.pattern)->text(), "recommended");
}

TEST(RefineSearch, BadSettingsAreRefused) {
  const PerceptualObjective o(parse_perceptual("perceptual:angles=1,patch=16,reference=16"));
  const Pattern p = catalog_pattern("centroid");
  RefineSettings s;
  s.step = 0;
  EXPECT_THROW(refine_pattern(p, refine_objective(o), s), ParameterError);
  s = {};
  s.min_step = 1;
  EXPECT_THROW(refine_pattern(p, refine_objective(o), s), ParameterError);
  s = {};
  s.max_tries = 0;
  EXPECT_THROW(refine_pattern(p, refine_objective(o), s), ParameterError);
  s = {};
  s.weight_steps = -1;
  EXPECT_THROW(refine_pattern(p, refine_objective(o), s), ParameterError);
  // Weight steps need a weight gradient, which a bare objective has not.
  s = {};
  s.weight_steps = 3;
  const RefineObjective bare{[](const Pattern&) { return 0.0; }, "zero", "zero", {}};
  EXPECT_NE(testing::error_message([&] { refine_pattern(p, bare, s); }).find("weight gradient"),
            std::string::npos);
}

// With an API every measured candidate is on its lattice: the result is, it
// is never worse than the start snapped, and a start that does not fit the
// profile (Metal takes 8 samples at most) is refused naming the rule.
TEST(RefineSearch, AnApisLatticeIsKept) {
  const PerceptualObjective o(parse_perceptual("perceptual:angles=2,patch=16,reference=16"));
  RefineSettings s;
  s.max_tries = 40;
  s.api = "vulkan";
  // Off the lattice, one sample 0.49 from the centre (the snap's nearest is -8/16).
  const Pattern start = single_pixel_pattern(
      "near-border", {{-0.49, 0.1}, {0.21, -0.33}, {0.12, 0.31}, {-0.23, -0.19}},
      {0.25, 0.25, 0.25, 0.25});
  const RefineResult r = refine_pattern(start, refine_objective(o), s);
  Pattern snapped = snap_to_lattice(start, kLatticeSteps);
  ASSERT_EQ(snapped.sets[0][0].x, -0.5);
  snapped.sets[0][0].x = -7.0 / 16;  // kept strictly inside
  EXPECT_EQ(r.start_value, o(snapped));
  EXPECT_EQ(off_lattice_sample(r.pattern, kLatticeSteps), "");
  for (const Vec2& v : r.pattern.sets[0]) {  // strictly inside: never the API's -8/16
    EXPECT_LE(std::abs(v.x), 7.0 / 16);
    EXPECT_LE(std::abs(v.y), 7.0 / 16);
  }
  EXPECT_LE(r.value, r.start_value);
  EXPECT_EQ(o(r.pattern), r.value);
  std::map<std::string, std::string> why(r.pattern.provenance.begin(), r.pattern.provenance.end());
  EXPECT_EQ(why["api"], "vulkan");
  s.api = "metal";
  EXPECT_NE(testing::error_message([&] {
              refine_pattern(resolve_pattern("aapat-16"), refine_objective(o), s);
            }).find("metal"),
            std::string::npos);
  s.api = "no-such-api";
  EXPECT_THROW(refine_pattern(start, refine_objective(o), s), Error);
}

// Any objective: the search minimizes what it is given (here the distance
// of the first sample from a point, whose minimum on the 1/256 steps is
// reached exactly) and records it under the objective's key.
TEST(RefineSearch, MinimizesAnyObjective) {
  const Pattern start = catalog_pattern("centroid");
  const RefineObjective toward{[](const Pattern& p) {
                                 const Vec2 d = p.sets[0][0] - Vec2{0.25, -0.125};
                                 return d.x * d.x + d.y * d.y;
                               },
                               "distance to (1/4, -1/8)",
                               "distance",
                               {}};
  RefineSettings s;
  s.max_tries = 400;
  const RefineResult r = refine_pattern(start, toward, s);
  EXPECT_NEAR(r.pattern.sets[0][0].x, 0.25, 1e-12);
  EXPECT_NEAR(r.pattern.sets[0][0].y, -0.125, 1e-12);
  EXPECT_EQ(r.value, 0);
  EXPECT_EQ(r.pattern.name, "centroid-distance");
  EXPECT_EQ(r.pattern.provenance.back().first, "distance");
  const auto doc = refine_json(toward, start, s, r);
  EXPECT_EQ(doc["objective"], "distance to (1/4, -1/8)");
  EXPECT_EQ(doc["after"], 0.0);
  EXPECT_FALSE(doc.contains("api"));
}

// Weight steps follow the objective's weight gradient, projected onto the
// constraints (non-negative, each kernel's summing to 1): a distance of
// msaa-4's weights to (0.4, 0.3, 0.2, 0.1), which the compass search, held
// to one evaluation, leaves alone, is brought to within the last step.
TEST(RefineSearch, WeightStepsFollowTheGradient) {
  const Pattern start = catalog_pattern("msaa-4");
  const std::vector<double> target = {0.4, 0.3, 0.2, 0.1};
  const RefineObjective toward{[&](const Pattern& p) {
                                 double sum = 0;
                                 for (size_t r = 0; r < 4; ++r)
                                   sum += std::pow(p.weights[0][r] - target[r], 2);
                                 return sum;
                               },
                               "distance to (0.4, 0.3, 0.2, 0.1)", "distance",
                               [&](const Pattern& p) {
                                 std::vector<std::vector<double>> g = {std::vector<double>(4)};
                                 for (size_t r = 0; r < 4; ++r)
                                   g[0][r] = 2 * (p.weights[0][r] - target[r]);
                                 return g;
                               }};
  RefineSettings s;
  s.max_tries = 1;
  s.weight_steps = 40;
  const RefineResult r = refine_pattern(start, toward, s);
  EXPECT_NEAR(r.compass_value, 0.05, 1e-12);  // the start: sum of 0.15^2, 0.05^2 twice
  EXPECT_GT(r.gradient_steps, 0);
  EXPECT_LT(r.value, 4 * std::pow(s.min_step, 2));
  double sum = 0;
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(r.pattern.weights[0][i], target[i], 2 * s.min_step);
    EXPECT_GE(r.pattern.weights[0][i], 0);
    sum += r.pattern.weights[0][i];
  }
  EXPECT_NEAR(sum, 1, 1e-12);
  EXPECT_EQ(r.pattern.sets, start.sets);  // the positions are held
  const auto doc = refine_json(toward, start, s, r);
  EXPECT_EQ(doc["weight_steps"], r.gradient_steps);
}

}  // namespace
}  // namespace aapat
