#include "aapat/study/perceptual_search.h"

#include <gtest/gtest.h>

#include "aapat/generate/catalog.h"
#include "testing/error_message.h"

namespace aapat {
namespace {

// The search never returns a pattern worse than its start, keeps a
// one-pixel pattern's samples strictly inside and its weights a
// non-negative partition of 1, and records the objective it refined under.
TEST(PerceptualSearch, NeverWorseAndOnTheConstraints) {
  const PerceptualObjective o(parse_perceptual("perceptual:angles=2,patch=16,reference=16"));
  PerceptualSearchSettings s;
  s.max_tries = 40;
  const Pattern start = catalog_pattern("msaa-4");
  const PerceptualSearchResult r = refine_perceptual(start, o, s);
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
  EXPECT_EQ(r.pattern.provenance.back().first, "refined");
}

TEST(PerceptualSearch, BadSettingsAreRefused) {
  const PerceptualObjective o(parse_perceptual("perceptual:angles=1,patch=16,reference=16"));
  const Pattern p = catalog_pattern("centroid");
  PerceptualSearchSettings s;
  s.step = 0;
  EXPECT_THROW(refine_perceptual(p, o, s), ParameterError);
  s = {};
  s.min_step = 1;
  EXPECT_THROW(refine_perceptual(p, o, s), ParameterError);
  s = {};
  s.max_tries = 0;
  EXPECT_THROW(refine_perceptual(p, o, s), ParameterError);
}

}  // namespace
}  // namespace aapat
